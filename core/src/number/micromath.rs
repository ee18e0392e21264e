//! `f32` with `micromath`'s fast approximations (feature `micromath`): [`F32Micro`].
//!
//! Only the square root is approximated (`micromath::F32Ext::sqrt`, a bit trick without a
//! Newton step: up to 6 % relative error, 2 % on average); every other operation is plain `f32`
//! ([`F32With`]). `micromath`'s `powf` is unusable for specular powers (61–99 % error), so
//! `powi` stays the trait's exact repeated squaring. The type exists so a report can show what
//! the approximate square root saves against what it costs in image quality.

use micromath::F32Ext;

use super::{F32With, SquareRoot};

/// `f32` with `micromath`'s approximate square root (`NAME = "f32-micromath"`).
pub type F32Micro = F32With<Micromath>;

/// `micromath`'s approximate square root, for [`F32Micro`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Micromath;

impl SquareRoot for Micromath {
    const NAME: &'static str = "f32-micromath";
    /// Up to 6 % (2⁻⁴ is 6.25 %).
    const SQRT_ERROR_EXPONENT: i32 = -4;

    /// `micromath`'s approximation: up to 6 % off. The bit trick scales exactly by even powers
    /// of two, like a correctly rounded square root.
    #[inline]
    fn sqrt(x: f32) -> f32 {
        F32Ext::sqrt(x)
    }
}
