//! `f64` and `f32`. Square roots come from `libm`, which is correctly rounded, so the host and
//! the firmware (software or hardware float) compute bit-identical results.

use super::Number;

macro_rules! float_number {
    ($type:ty, $name:literal, $limit:expr, $sqrt:path, $bits:ty, $mantissa:literal, $bias:literal) => {
        impl Number for $type {
            const NAME: &'static str = $name;
            const SCENE_LIMIT: f64 = $limit;
            const FLOATING_POINT: bool = true;
            const RESOLUTION: Self = 0.0;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const MAX: Self = <$type>::MAX;

            fn from_f64(value: f64) -> Self {
                if value.is_nan() {
                    0.0
                } else {
                    (value as $type).clamp(<$type>::MIN, <$type>::MAX)
                }
            }

            fn to_f64(self) -> f64 {
                self as f64
            }

            fn write_literal(self, out: &mut dyn core::fmt::Write) -> core::fmt::Result {
                write!(out, "{}::from_bits({:#x})", stringify!($type), self.to_bits())
            }

            fn from_i32(value: i32) -> Self {
                value as $type
            }

            fn sqrt(self) -> Self {
                if self > 0.0 {
                    $sqrt(self)
                } else {
                    0.0
                }
            }

            fn checked_div(self, divisor: Self) -> Option<Self> {
                let quotient = self / divisor;
                // One comparison for the usual, finite quotient: a zero divisor gives an
                // infinity or NaN, which fails it as an overflow does, and is told apart only
                // then (the division by zero raises no trap, it only sets a sticky flag).
                // `clamp(MIN, MAX)` would pay two compare-and-branch pairs on an FPU without
                // min/max instructions.
                if quotient.abs() <= <$type>::MAX {
                    Some(quotient)
                } else if divisor == 0.0 {
                    None
                } else if quotient > 0.0 {
                    Some(<$type>::MAX)
                } else if quotient < 0.0 {
                    Some(<$type>::MIN)
                } else {
                    Some(quotient)
                }
            }

            /// The sign bit cleared: one instruction on an FPU (`VABS`), one `BIC` without.
            /// Unlike the default it maps −0 to +0, which compares equal to it.
            fn abs(self) -> Self {
                <$type>::abs(self)
            }

            fn floor_to_i32(self) -> i32 {
                // ⌊x⌋ without libm's floor (a call, and integer code without an FPU): `as`
                // truncates, saturates and maps NaN to 0; a negative non-integer then steps
                // down one. Exact: a truncated value too large for the type's mantissa came
                // from an integer, which converts back unchanged.
                let truncated = self as i32;
                if (truncated as $type) > self {
                    truncated.saturating_sub(1)
                } else {
                    truncated
                }
            }

            /// Truncation: `as` saturates and maps NaN to 0.
            fn to_i32_monotone(self) -> i32 {
                self as i32
            }

            // Inline on hosts, where it stayed out of line and cost 4 % of a snooker frame
            // through `shadow_origin`; not hinted on the Cortex-M, whose LTO build folds it
            // where it pays and whose snooker frame the hint made 34 K instructions longer.
            #[cfg_attr(not(target_arch = "arm"), inline)]
            fn times_power_of_two(self, exponent: i32) -> Self {
                // In steps the factor itself can represent (a normal power of two): almost
                // always one, tested first.
                let limit = $bias - 1;
                if (-limit..=limit).contains(&exponent) {
                    return self * <$type>::from_bits(((exponent + $bias) as $bits) << $mantissa);
                }
                let mut value = self;
                let mut remaining = exponent;
                while remaining != 0 {
                    let step = remaining.clamp(-limit, limit);
                    let factor = <$type>::from_bits(((step + $bias) as $bits) << $mantissa);
                    value *= factor;
                    remaining -= step;
                }
                value
            }

            fn binary_exponent(self) -> Option<i32> {
                if self == 0.0 || !self.is_finite() {
                    return None;
                }
                let biased = ((self.to_bits() >> $mantissa) as i32) & (2 * $bias + 1);
                if biased != 0 {
                    Some(biased - $bias)
                } else {
                    // Subnormal: scale into the normal range first.
                    Number::binary_exponent(self.times_power_of_two($mantissa)).map(|e| e - $mantissa)
                }
            }
        }
    };
}

// Beyond 10¹⁸ a ray's parameter is so large that its steps (2⁻⁵² of it, over 200 units at
// 10¹⁸·4) exceed the objects' sizes, and a hit is rounding noise: fuzzing found an eye 4·10³⁹
// away "hitting" objects that the same eye 10¹⁸ away rightly misses, and the optimizations'
// bounds (rightly) disagreeing with it (docs/fuzzing.md, finding 3). The same range as f32's.
float_number!(f64, "f64", 1e18, libm::sqrt, u64, 52, 1023);
// Three squares of 10¹⁸ (3·10³⁶) stay below f32::MAX (3.4·10³⁸): no infinities from dot products.
float_number!(f32, "f32", 1e18, libm::sqrtf, u32, 23, 127);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn powi_matches_repeated_multiplication() {
        assert_eq!(Number::powi(0.5f64, 3), 0.125);
        assert_eq!(Number::powi(2.0f64, 0), 1.0);
        assert_eq!(Number::powi(0.9f64, 100_000), 0.0);
    }

    #[test]
    fn zero_divisor_is_none_and_overflow_saturates() {
        assert_eq!(1.0f32.checked_div(0.0), None);
        assert_eq!(1e30f32.checked_div(1e-30), Some(f32::MAX));
    }

    #[test]
    fn powers_of_two_and_exponents() {
        assert_eq!(3.0f64.times_power_of_two(-2), 0.75);
        assert_eq!(1.5f32.times_power_of_two(-130), 1.5 * f32::from_bits(1 << 23) / 16.0);
        assert_eq!(1.0f64.times_power_of_two(-1074), f64::from_bits(1));
        assert_eq!(Number::binary_exponent(0.75f64), Some(-1));
        assert_eq!(Number::binary_exponent(-8.0f32), Some(3));
        assert_eq!(Number::binary_exponent(f64::from_bits(1)), Some(-1074));
        assert_eq!(Number::binary_exponent(0.0f32), None);
    }

    #[test]
    fn sqrt_of_negative_is_zero() {
        assert_eq!(Number::sqrt(-4.0f64), 0.0);
        assert_eq!(Number::sqrt(4.0f32), 2.0);
    }

    /// The libm-free floor equals libm's floor saturated to `i32`, on the edges (±0, NaN,
    /// infinities, ±2³¹ and beyond, halves, values just below integers) and on a sweep.
    #[test]
    fn floor_to_i32_is_floor_saturated() {
        let edges = [0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.999_999, -2.999_999, 2_147_483_647.0, 2_147_483_647.5, 2_147_483_648.0, -2_147_483_648.0, -2_147_483_648.5, -2_147_483_649.0, 1e12, -1e12, f64::MAX, f64::MIN, f64::INFINITY, f64::NEG_INFINITY, f64::NAN, f64::from_bits(1), -f64::from_bits(1)];
        let sweep = (-4000..4000).map(|i| f64::from(i) * 0.37 + 1e-9 * f64::from(i % 7));
        for x in edges.into_iter().chain(sweep) {
            assert_eq!(Number::floor_to_i32(x), libm::floor(x) as i32, "f64 {x}");
            let y = x as f32;
            assert_eq!(Number::floor_to_i32(y), libm::floorf(y) as i32, "f32 {y}");
        }
        for bits in (0..u32::MAX).step_by(9973) {
            let y = f32::from_bits(bits);
            assert_eq!(Number::floor_to_i32(y), libm::floorf(y) as i32, "f32 bits {bits:#x}");
        }
    }
}
