//! The number type the tracer computes in.
//!
//! Everything from ray generation to shading is generic over [`Number`], so the same code runs
//! in `f64` (the reference), `f32`, or, on a microcontroller without an FPU, fixed point or a
//! lean software floating point (`SoftFloat`). The trait avoids anything a fixed-point type
//! cannot do: there are no infinities or NaNs, a division states what happens when the
//! divisor is zero, and powers are integer powers.
//! Scene set-up (matrix composition, inversion, trigonometry) is done once in `f64` and
//! converted with [`Number::from_f64`]; only per-pixel work runs in the number type.
//!
//! [`F32With<S>`](F32With) is `f32` with the square root of a [`SquareRoot`] `S` and every
//! other operation `f32`'s, bit for bit: `F32Micro` is `F32With<Micromath>` (feature
//! `micromath`, an approximate square root), and the firmware on the Cortex-M4F computes its
//! `f32` as `F32With<VsqrtF32>`, the FPU's correctly rounded `vsqrt.f32`, which this crate
//! cannot emit (it forbids `unsafe`, and stable `core` has no `f32` square root); that build's
//! images stay `f32`'s, and its name is `f32`.

mod f32_with;
mod kind;
#[cfg(feature = "fixed-point")]
mod fixed;
mod float;
#[cfg(feature = "micromath")]
mod micromath;
#[cfg(feature = "soft-float")]
mod soft_float;

pub use f32_with::{F32With, SquareRoot};
pub use kind::NumberKind;
#[cfg(feature = "fixed-point")]
pub use fixed::{Fixed, Fixed16};
#[cfg(feature = "micromath")]
pub use micromath::{F32Micro, Micromath};
#[cfg(feature = "soft-float")]
pub use soft_float::SoftFloat;

use core::fmt::Debug;
use core::ops::{Add, Mul, Neg, Sub};

/// A real-number type for the tracer's per-pixel arithmetic.
pub trait Number:
    Copy
    + 'static
    + PartialOrd
    + PartialEq
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
{
    /// A short name for reports and the command line (`f64`, `f32`, ...).
    const NAME: &'static str;
    const ZERO: Self;
    const ONE: Self;
    /// The largest finite value: "no hit yet" and "unbounded shadow ray".
    const MAX: Self;
    /// The value whose every byte is zero: a placeholder in storage that preparation writes
    /// before anything reads it (`Scene::UNPREPARED`), so that the firmware's scene, a `static`
    /// of such placeholders, is zero-initialised RAM (`.bss`) and takes no flash. It is
    /// [`Number::ZERO`] but in `SoftFloat`, whose zero has a low exponent: there it is no
    /// number to compute with.
    const ZEROED: Self = Self::ZERO;

    /// Converts, saturating to the representable range. Used at scene set-up only.
    fn from_f64(value: f64) -> Self;
    fn to_f64(self) -> f64;
    fn from_i32(value: i32) -> Self;

    /// The square root; zero for zero and negative inputs.
    fn sqrt(self) -> Self;

    /// `self / divisor`, or `None` when the divisor is zero. Quotients too large for the type
    /// saturate.
    fn checked_div(self, divisor: Self) -> Option<Self>;

    /// The largest integer not above `self`, saturating to the `i32` range.
    fn floor_to_i32(self) -> i32;

    /// An integer within one of `self` that never decreases as `self` grows, saturating to
    /// the `i32` range: ⌊self⌋ or `self` truncated toward zero, whichever the type computes
    /// more cheaply (floating point truncates: one conversion). For conservative integer
    /// bounds, which need only the order kept, and for values known not to be negative, where
    /// both are ⌊self⌋.
    fn to_i32_monotone(self) -> i32 {
        self.floor_to_i32()
    }

    fn abs(self) -> Self {
        if self < Self::ZERO {
            -self
        } else {
            self
        }
    }

    fn min(self, other: Self) -> Self {
        if other < self {
            other
        } else {
            self
        }
    }

    fn max(self, other: Self) -> Self {
        if other > self {
            other
        } else {
            self
        }
    }

    /// `self` raised to an integer power by repeated squaring (the specular term: §4.2.4 uses
    /// `pow`, which a fixed-point type cannot provide in general). The result starts as the
    /// power of the exponent's lowest set bit rather than as one times it, and the loop ends
    /// with the last product, not with a square nobody uses: the same products in the same
    /// order (one times a value is exact in every type), fewer instructions.
    fn powi(self, exponent: u32) -> Self {
        if exponent == 0 {
            return Self::ONE;
        }
        let mut base = self;
        let mut remaining = exponent;
        while remaining & 1 == 0 {
            base = base * base;
            remaining >>= 1;
        }
        let mut result = base;
        remaining >>= 1;
        while remaining > 0 {
            base = base * base;
            if remaining & 1 == 1 {
                result = result * base;
            }
            remaining >>= 1;
        }
        result
    }

    /// `a·b` of two 3-vectors. A type with a wider accumulator overrides this.
    fn dot3(a: [Self; 3], b: [Self; 3]) -> Self {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    /// `|v|` of a 3-vector. A type with a narrow range overrides this to scale first.
    fn length3(v: [Self; 3]) -> Self {
        Self::dot3(v, v).sqrt()
    }

    /// The smallest positive step of a fixed-point type (its rounding error is absolute); zero
    /// for floating point, whose steps are relative to the value.
    const RESOLUTION: Self;

    /// Whether the type is floating point: its precision is relative, so scaling by a power of
    /// two changes no result, and the rescaling that keeps fixed point precise can be skipped.
    const FLOATING_POINT: bool;

    /// `self·2^exponent`: exact in floating point (away from overflow and underflow); in fixed
    /// point exact for positive exponents (saturating) and rounded to nearest for negative ones.
    fn times_power_of_two(self, exponent: i32) -> Self;

    /// The `e` with `2^e ≤ |self| < 2^(e+1)`; `None` for zero.
    fn binary_exponent(self) -> Option<i32>;

    /// Writes a constant expression of exactly this value (bit for bit) that a crate using
    /// `microtrace` compiles: how the firmware's build script puts a scene prepared on the host
    /// into flash in the number type.
    fn write_literal(self, out: &mut dyn core::fmt::Write) -> core::fmt::Result;

    /// The relative error of [`Number::sqrt`] is below 2^this. Conservative bounds built with
    /// square roots (the shadow table's cones) widen by it; an approximate square root
    /// (`f32-micromath`) overrides it.
    const SQRT_ERROR_EXPONENT: i32 = -20;

    /// Whether shadow culling's conservative bounds (the light footprints' chords and boxes,
    /// the capsule test) hold for shadow rays traced in this type. Their margins assume unit
    /// directions to within the square root's error and the type's resolution; in `fixed16`
    /// a direction from a far light (a reciprocal of a distance, in steps of 2⁻¹⁶) and in
    /// `f32-micromath` (a 6 % square root) is farther off, and fuzzing found shadows lost
    /// (docs/fuzzing.md, docs/deviations.md). False: shadow rays are not culled, so every
    /// optimization still renders the unoptimized image.
    const SHADOW_CULLING_HOLDS: bool = true;

    /// Whether Sortlist's depth bounds hold for primary rays traced in this type: they assume
    /// unit directions, which `f32-micromath`'s square root leaves up to 6 % off (a hit then
    /// lies nearer in `t` than the bound), and `fixed16`'s steps miss their margin near its
    /// range (fuzzing). False: Sortlist orders the tests but never ends the loop early.
    const DEPTH_BOUNDS_HOLD: bool = true;

    /// The documented range of scene values: the largest magnitude [`Number::can_represent`]
    /// accepts (10¹⁸ for `f64` and `f32`).
    const SCENE_LIMIT: f64 = f64::INFINITY;

    /// Whether a scene value (a coordinate, a light position, a matrix entry) of this size is
    /// safe in this type: it converts without saturating, and the squares and dot products the
    /// tracer forms from such values stay in range. Scene preparation uses it to reject a
    /// scene that does not fit and name the object. Values too small to resolve are accepted
    /// (they round to zero or lose relative precision, which the caller cannot act on).
    fn can_represent(value: f64) -> bool {
        value.is_finite() && value.abs() <= Self::SCENE_LIMIT
    }
}

/// Every number type's [`Number::ZEROED`]: a table of numbers starts all zero bytes.
impl<N: Number> crate::storage::Unset for N {
    const UNSET: Self = N::ZEROED;
}
