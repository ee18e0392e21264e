//! `f32` with a square root of the caller's choice: [`F32With<S>`](F32With).
//!
//! Every operation except the square root is plain `f32`'s (the `Number` impl in `float.rs`),
//! so with a correctly rounded [`SquareRoot`] the type computes bit for bit what `f32` does.
//! That lets code outside this `forbid(unsafe_code)` crate supply a faster square root (the
//! firmware's `vsqrt.f32` on the Cortex-M4F), or an approximate one ([`F32Micro`](super::F32Micro),
//! micromath's bit trick), without a second copy of the arithmetic.

use core::cmp::Ordering;
use core::fmt;
use core::marker::PhantomData;
use core::ops::{Add, Mul, Neg, Sub};

use super::Number;

/// The square root of an [`F32With`].
///
/// [`SquareRoot::sqrt`] is called only for finite `x > 0` (`F32With` answers zero for zero and
/// negative inputs itself). It must scale exactly by even powers of two,
/// `sqrt(4^k·x) = 2^k·sqrt(x)` away from overflow and underflow (a correctly rounded square
/// root does; so does micromath's bit trick), since `F32With` is floating point
/// ([`Number::FLOATING_POINT`]) and the tracer may rescale by powers of two before a square
/// root.
pub trait SquareRoot: 'static {
    /// The number type's name in reports and on the command line ([`Number::NAME`]).
    const NAME: &'static str;
    /// The relative error of [`SquareRoot::sqrt`] is below 2^this
    /// ([`Number::SQRT_ERROR_EXPONENT`]); the default is the trait's, for a correctly rounded
    /// square root.
    const SQRT_ERROR_EXPONENT: i32 = -20;
    /// `√x` for finite `x > 0`.
    fn sqrt(x: f32) -> f32;
}

/// `f32` whose square root is `S`'s: every other operation is plain `f32`'s.
///
/// The value is the public field `.0`; [`F32With::new`] builds one.
pub struct F32With<S>(pub f32, PhantomData<fn() -> S>);

impl<S> F32With<S> {
    #[inline]
    pub const fn new(value: f32) -> Self {
        Self(value, PhantomData)
    }
}

// By hand rather than derived: a derive would require `S` itself to be `Clone`, `PartialEq`, ...
impl<S> Clone for F32With<S> {
    #[inline]
    fn clone(&self) -> Self {
        *self
    }
}

impl<S> Copy for F32With<S> {}

impl<S> Default for F32With<S> {
    #[inline]
    fn default() -> Self {
        Self::new(0.0)
    }
}

impl<S> PartialEq for F32With<S> {
    #[inline]
    fn eq(&self, other: &Self) -> bool {
        self.0 == other.0
    }
}

impl<S> PartialOrd for F32With<S> {
    #[inline]
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.0.partial_cmp(&other.0)
    }
}

impl<S: SquareRoot> fmt::Debug for F32With<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "F32With<{}>({:?})", S::NAME, self.0)
    }
}

impl<S> fmt::Display for F32With<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl<S> Add for F32With<S> {
    type Output = Self;
    #[inline]
    fn add(self, other: Self) -> Self {
        Self::new(self.0 + other.0)
    }
}

impl<S> Sub for F32With<S> {
    type Output = Self;
    #[inline]
    fn sub(self, other: Self) -> Self {
        Self::new(self.0 - other.0)
    }
}

impl<S> Mul for F32With<S> {
    type Output = Self;
    #[inline]
    fn mul(self, other: Self) -> Self {
        Self::new(self.0 * other.0)
    }
}

impl<S> Neg for F32With<S> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.0)
    }
}

#[inline]
fn unwrap3<S>(v: [F32With<S>; 3]) -> [f32; 3] {
    [v[0].0, v[1].0, v[2].0]
}

/// Everything but `sqrt` (and `length3`, which is built on it) forwards to `f32`'s own
/// implementation, so the results are `f32`'s bit for bit even where `f32` overrides a default.
impl<S: SquareRoot> Number for F32With<S> {
    const NAME: &'static str = S::NAME;

    fn write_literal(self, out: &mut dyn core::fmt::Write) -> core::fmt::Result {
        write!(out, "microtrace::number::F32With::new(f32::from_bits({:#x}))", self.0.to_bits())
    }
    const SCENE_LIMIT: f64 = <f32 as Number>::SCENE_LIMIT;
    const FLOATING_POINT: bool = <f32 as Number>::FLOATING_POINT;
    const SQRT_ERROR_EXPONENT: i32 = S::SQRT_ERROR_EXPONENT;
    /// A square root as good as the correctly rounded one (within 2⁻²⁰) keeps `f32`'s bounds.
    const SHADOW_CULLING_HOLDS: bool = S::SQRT_ERROR_EXPONENT <= -20;
    const DEPTH_BOUNDS_HOLD: bool = S::SQRT_ERROR_EXPONENT <= -20;
    const RESOLUTION: Self = Self::new(<f32 as Number>::RESOLUTION);
    const ZERO: Self = Self::new(<f32 as Number>::ZERO);
    const ONE: Self = Self::new(<f32 as Number>::ONE);
    const MAX: Self = Self::new(<f32 as Number>::MAX);

    #[inline]
    fn from_f64(value: f64) -> Self {
        Self::new(<f32 as Number>::from_f64(value))
    }

    #[inline]
    fn to_f64(self) -> f64 {
        <f32 as Number>::to_f64(self.0)
    }

    #[inline]
    fn from_i32(value: i32) -> Self {
        Self::new(<f32 as Number>::from_i32(value))
    }

    /// `S`'s square root for positive inputs; zero for zero, negative inputs and NaN, as `f32`.
    #[inline]
    fn sqrt(self) -> Self {
        if self.0 > 0.0 {
            Self::new(S::sqrt(self.0))
        } else {
            Self::ZERO
        }
    }

    #[inline]
    fn checked_div(self, divisor: Self) -> Option<Self> {
        <f32 as Number>::checked_div(self.0, divisor.0).map(Self::new)
    }

    #[inline]
    fn floor_to_i32(self) -> i32 {
        <f32 as Number>::floor_to_i32(self.0)
    }

    #[inline]
    fn to_i32_monotone(self) -> i32 {
        <f32 as Number>::to_i32_monotone(self.0)
    }

    #[inline]
    fn abs(self) -> Self {
        Self::new(<f32 as Number>::abs(self.0))
    }

    #[inline]
    fn min(self, other: Self) -> Self {
        Self::new(<f32 as Number>::min(self.0, other.0))
    }

    #[inline]
    fn max(self, other: Self) -> Self {
        Self::new(<f32 as Number>::max(self.0, other.0))
    }

    #[inline]
    fn powi(self, exponent: u32) -> Self {
        Self::new(<f32 as Number>::powi(self.0, exponent))
    }

    #[inline]
    fn dot3(a: [Self; 3], b: [Self; 3]) -> Self {
        Self::new(<f32 as Number>::dot3(unwrap3(a), unwrap3(b)))
    }

    // `length3` keeps the trait's default, `dot3(v, v).sqrt()`, which is `f32`'s with `S`'s
    // square root.

    #[inline]
    fn times_power_of_two(self, exponent: i32) -> Self {
        Self::new(<f32 as Number>::times_power_of_two(self.0, exponent))
    }

    #[inline]
    fn binary_exponent(self) -> Option<i32> {
        <f32 as Number>::binary_exponent(self.0)
    }

    #[inline]
    fn can_represent(value: f64) -> bool {
        <f32 as Number>::can_represent(value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A correctly rounded square root: libm's, the one plain `f32` uses.
    struct Libm;

    impl SquareRoot for Libm {
        const NAME: &'static str = "f32-libm";
        fn sqrt(x: f32) -> f32 {
            libm::sqrtf(x)
        }
    }

    type F = F32With<Libm>;

    /// Deterministic xorshift64*.
    struct Rng(u64);

    impl Rng {
        fn next_u64(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
        }

        /// Values of every size and sign, including the special ones the tracer meets.
        fn value(&mut self) -> f32 {
            const SPECIAL: [f32; 12] = [0.0, -0.0, 1.0, -1.0, 0.5, f32::MAX, -f32::MAX, f32::MIN_POSITIVE, 1e-40, -1e-40, 1e18, -3.0];
            let bits = self.next_u64();
            match bits % 4 {
                0 => SPECIAL[(bits >> 8) as usize % SPECIAL.len()],
                // Any finite bit pattern (subnormals included).
                1 => {
                    let value = f32::from_bits((bits >> 32) as u32);
                    if value.is_finite() {
                        value
                    } else {
                        2.0
                    }
                }
                // The tracer's ranges: about ±2000.
                _ => ((bits >> 11) as f64 / (1u64 << 53) as f64 * 4000.0 - 2000.0) as f32,
            }
        }
    }

    fn same(a: F, b: f32, what: &str, inputs: &[f32]) {
        assert_eq!(a.0.to_bits(), b.to_bits(), "{what} of {inputs:?}: F32With {} against f32 {}", a.0, b);
    }

    #[test]
    fn with_a_correctly_rounded_sqrt_it_is_plain_f32() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        for _ in 0..20_000 {
            let (x, y, z) = (rng.value(), rng.value(), rng.value());
            let (a, b, c) = (F::new(x), F::new(y), F::new(z));
            let inputs = [x, y, z];
            same(a + b, x + y, "+", &inputs);
            same(a - b, x - y, "-", &inputs);
            same(a * b, x * y, "*", &inputs);
            same(-a, -x, "neg", &inputs);
            same(a.sqrt(), Number::sqrt(x), "sqrt", &inputs);
            same(Number::abs(a), Number::abs(x), "abs", &inputs);
            same(Number::min(a, b), Number::min(x, y), "min", &inputs);
            same(Number::max(a, b), Number::max(x, y), "max", &inputs);
            let exponent = (rng.next_u64() % 12) as u32;
            same(a.powi(exponent), Number::powi(x, exponent), "powi", &inputs);
            same(F::dot3([a, b, c], [c, a, b]), f32::dot3([x, y, z], [z, x, y]), "dot3", &inputs);
            same(F::length3([a, b, c]), f32::length3([x, y, z]), "length3", &inputs);
            match (a.checked_div(b), x.checked_div(y)) {
                (Some(q), Some(r)) => same(q, r, "checked_div", &inputs),
                (None, None) => {}
                (q, r) => panic!("checked_div of {inputs:?}: {q:?} against {r:?}"),
            }
            assert_eq!(a.floor_to_i32(), x.floor_to_i32(), "floor_to_i32 of {x}");
            let shift = (rng.next_u64() % 301) as i32 - 150;
            same(a.times_power_of_two(shift), x.times_power_of_two(shift), "times_power_of_two", &inputs);
            assert_eq!(Number::binary_exponent(a), Number::binary_exponent(x), "binary_exponent of {x}");
            assert_eq!(a.to_f64().to_bits(), Number::to_f64(x).to_bits(), "to_f64 of {x}");
            assert_eq!(a == b, x == y);
            assert_eq!(a.partial_cmp(&b), x.partial_cmp(&y));
            let wide = f64::from(x) * 1e3 + f64::from(y);
            same(F::from_f64(wide), <f32 as Number>::from_f64(wide), "from_f64", &inputs);
            assert_eq!(F::can_represent(wide), f32::can_represent(wide));
            let integer = rng.next_u64() as i32;
            same(F::from_i32(integer), <f32 as Number>::from_i32(integer), "from_i32", &inputs);
        }
        for special in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e300, -1e300] {
            same(F::from_f64(special), <f32 as Number>::from_f64(special), "from_f64", &[]);
            assert_eq!(F::can_represent(special), f32::can_represent(special));
        }
    }

    #[test]
    fn constants_are_f32s_and_the_name_and_error_are_the_square_roots() {
        same(F::ZERO, 0.0, "ZERO", &[]);
        same(F::ONE, 1.0, "ONE", &[]);
        same(F::MAX, f32::MAX, "MAX", &[]);
        same(F::RESOLUTION, <f32 as Number>::RESOLUTION, "RESOLUTION", &[]);
        assert_eq!(F::SCENE_LIMIT, <f32 as Number>::SCENE_LIMIT);
        assert_eq!(F::FLOATING_POINT, <f32 as Number>::FLOATING_POINT);
        assert_eq!(F::NAME, "f32-libm");
        assert_eq!(F::SQRT_ERROR_EXPONENT, <f32 as Number>::SQRT_ERROR_EXPONENT);
        assert_eq!(F::default(), F::ZERO);
    }

    #[test]
    fn sqrt_of_zero_negative_and_nan_is_zero_without_calling_the_square_root() {
        struct Panics;
        impl SquareRoot for Panics {
            const NAME: &'static str = "panics";
            fn sqrt(x: f32) -> f32 {
                panic!("called for {x}")
            }
        }
        for x in [0.0, -0.0, -1.0, -f32::MIN_POSITIVE, f32::NAN] {
            assert_eq!(F32With::<Panics>::new(x).sqrt().0.to_bits(), 0);
        }
    }
}
