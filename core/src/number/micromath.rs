//! `f32` with `micromath`'s fast approximations (feature `micromath`): [`F32Micro`].
//!
//! Only the square root is approximated (`micromath::F32Ext::sqrt`, a bit trick without a
//! Newton step: up to 6 % relative error, 2 % on average); every other operation is plain `f32`.
//! `micromath`'s `powf` is unusable for specular powers (61–99 % error), so `powi` stays the
//! trait's exact repeated squaring. The type exists so a report can show what the approximate
//! square root saves against what it costs in image quality.

use core::fmt;
use core::ops::{Add, Mul, Neg, Sub};

use micromath::F32Ext;

use super::Number;

/// `f32` with `micromath`'s approximate square root (`NAME = "f32-micromath"`).
#[derive(Clone, Copy, Default, PartialEq, PartialOrd)]
pub struct F32Micro(pub f32);

impl fmt::Debug for F32Micro {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "F32Micro({:?})", self.0)
    }
}

impl fmt::Display for F32Micro {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl Add for F32Micro {
    type Output = Self;
    #[inline]
    fn add(self, other: Self) -> Self {
        Self(self.0 + other.0)
    }
}

impl Sub for F32Micro {
    type Output = Self;
    #[inline]
    fn sub(self, other: Self) -> Self {
        Self(self.0 - other.0)
    }
}

impl Mul for F32Micro {
    type Output = Self;
    #[inline]
    fn mul(self, other: Self) -> Self {
        Self(self.0 * other.0)
    }
}

impl Neg for F32Micro {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self(-self.0)
    }
}

impl Number for F32Micro {
    const NAME: &'static str = "f32-micromath";
    const SCENE_LIMIT: f64 = <f32 as Number>::SCENE_LIMIT;
    // The bit-trick square root scales exactly by even powers of two, like a correctly rounded one.
    const FLOATING_POINT: bool = true;
    /// Up to 6 % (2⁻⁴ is 6.25 %).
    const SQRT_ERROR_EXPONENT: i32 = -4;
    const RESOLUTION: Self = Self(0.0);
    const ZERO: Self = Self(0.0);
    const ONE: Self = Self(1.0);
    const MAX: Self = Self(f32::MAX);

    fn from_f64(value: f64) -> Self {
        Self(<f32 as Number>::from_f64(value))
    }

    fn to_f64(self) -> f64 {
        f64::from(self.0)
    }

    fn from_i32(value: i32) -> Self {
        Self(value as f32)
    }

    /// `micromath`'s approximation: up to 6 % off.
    fn sqrt(self) -> Self {
        if self.0 > 0.0 {
            Self(F32Ext::sqrt(self.0))
        } else {
            Self::ZERO
        }
    }

    fn checked_div(self, divisor: Self) -> Option<Self> {
        self.0.checked_div(divisor.0).map(Self)
    }

    fn floor_to_i32(self) -> i32 {
        self.0.floor_to_i32()
    }

    fn times_power_of_two(self, exponent: i32) -> Self {
        Self(self.0.times_power_of_two(exponent))
    }

    fn binary_exponent(self) -> Option<i32> {
        Number::binary_exponent(self.0)
    }
}
