//! Fixed-point number types for microcontrollers without an FPU, stored in the `fixed` crate's
//! types (feature `fixed-point`).
//!
//! - [`Fixed`] (`NAME = "fixed"`, the recommended one): Q32.32 in an `i64` ([`I32F32`]).
//!   Range ±2³¹ (≈ ±2.1·10⁹), resolution 2⁻³² (≈ 2.3·10⁻¹⁰). Wide enough that the tracer's
//!   one-type-for-everything design works unchanged: world coordinates up to ±26 000 and their
//!   squares fit, and unit directions scaled by 1/radius into object space keep ≥ 25
//!   significant bits. Both thesis scenes render pixel-identical to `f64` at 128x64 and at
//!   full size. Multiplication and `dot3` form exact 128-bit products from 32×32→64 multiplies
//!   (`SMULL`/`UMULL`/`MLA`) and round once; division is Knuth's algorithm D on 32-bit digits
//!   using the 32-bit hardware `UDIV`; the square root is `u64::isqrt` of the normalised value.
//! - [`Fixed16`] (`NAME = "fixed16"`, for comparison): Q16.16 in an `i32` ([`I16F16`]) with
//!   64-bit intermediate products, a `dot3` that accumulates three exact products before one
//!   rounding, and a `length3`/`sqrt` through an exact 64-bit integer square root. About 2.5x
//!   cheaper per pixel than `Fixed` on Cortex-M3, but a unit direction is only good to 2⁻¹⁶ and
//!   object-space directions (scaled by 1/radius) lose most of their bits: about 1 % of
//!   silhouette rays flip on the snooker balls, and the images have speckles.
//!
//! Measured on Cortex-M3 (QEMU lm3s6965evb, `-icount`, instructions, `opt-level = "s"`, LTO),
//! per operation including the call: `Fixed` add 12, mul 43, dot3 ≈ 135, div 240, sqrt 217;
//! software `f32` add 77, mul 48, dot3 ≈ 320, div 178, sqrt (libm) 172; `Fixed16` add 2,
//! mul 15, dot3 ≈ 40, div 165, sqrt 170.
//!
//! Both saturate instead of wrapping: every operator is implemented on the raw bits with
//! explicit saturating, checked or provably non-overflowing integer operations, never with
//! `fixed`'s own operators (which panic on overflow in debug builds). Nothing here can panic.

use core::fmt;
use core::ops::{Add, Mul, Neg, Sub};

use fixed::types::{I16F16, I32F32};

use super::Number;

// ---------------------------------------------------------------------------------------------
// Q32.32
// ---------------------------------------------------------------------------------------------

/// Q32.32 fixed point: the recommended number type for FPU-less targets (see the module docs).
#[derive(Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Fixed(pub I32F32);

/// 2³²: one unit of `Fixed` in raw bits.
const ONE_32: f64 = 4_294_967_296.0;

impl Fixed {
    /// The largest magnitude [`Number::can_represent`] accepts for a scene value: three squares
    /// of it still add up below the range (3·26 000² ≈ 2.03·10⁹ < 2³¹), so `dot3` of two such
    /// vectors never saturates.
    pub const COORDINATE_LIMIT: f64 = 26_000.0;

    pub const fn from_bits(bits: i64) -> Self {
        Self(I32F32::from_bits(bits))
    }

    pub const fn to_bits(self) -> i64 {
        self.0.to_bits()
    }
}

/// The exact 128-bit product `a·b` (of two raw Q32.32 values, so it is Q64.64), from 32-bit
/// halves: one `SMULL` (high × high), one `UMULL` (low × low) and two mixed products, summed
/// with word-shifted adds. Every partial product fits its type: |hi·hi| ≤ 2⁶², |lo·hi| < 2⁶³,
/// and the sum is at most 2¹²⁶ in magnitude.
#[inline(always)]
fn wide_mul(a: i64, b: i64) -> i128 {
    let (a_high, a_low) = (a >> 32, i64::from(a as u32));
    let (b_high, b_low) = (b >> 32, i64::from(b as u32));
    let high = a_high * b_high; // i32 × i32
    let middle = i128::from(a_high * b_low) + i128::from(a_low * b_high); // i32 × u32, twice
    let low = (a_low as u64) * (b_low as u64); // u32 × u32
    (i128::from(high) << 64) + (middle << 32) + i128::from(low)
}

/// A Q64.64 value (a product or a sum of products) rounded to Q32.32: to nearest, ties toward
/// +∞, saturating.
#[inline(always)]
fn round_q64(wide: i128) -> i64 {
    let rounded = wide.saturating_add(1 << 31);
    let result = (rounded >> 32) as i64; // bits 32..95
    let top = (rounded >> 64) as i64; // bits 64..127
    // It fits when bits 95..127 are all copies of the sign, i.e. bits 64..127 equal the upper
    // half of the result sign-extended.
    if top == result >> 32 {
        result
    } else if top < 0 {
        i64::MIN
    } else {
        i64::MAX
    }
}

/// `a·b` of two Q32.32 values, rounded to nearest, saturating.
#[inline]
fn mul_q32(a: i64, b: i64) -> i64 {
    round_q64(wide_mul(a, b))
}

/// `(u1·2³² + u0) / v` for a normalised divisor (top bit set) and `u1 < v`, so the quotient
/// fits 32 bits: Hacker's Delight `divlu`, two 16-bit quotient digits from the 32-bit hardware
/// `UDIV` (Cortex-M3 has no 64-bit division). All intermediate values fit `u32` as the
/// algorithm guarantees; the wrapping operations only keep debug builds from checking that.
#[inline]
fn divlu(u1: u32, u0: u32, v: u32) -> u32 {
    const B: u32 = 1 << 16;
    // vn1 ≥ 2^15 for the normalised divisor; `max(1)` changes nothing then, and shows the
    // compiler that the divisions below cannot be by zero (no panic path).
    let (vn1, vn0) = ((v >> 16).max(1), v & 0xFFFF);
    let (un1, un0) = (u0 >> 16, u0 & 0xFFFF);
    let mut q1 = u1 / vn1;
    let mut rhat = u1 - q1 * vn1;
    while q1 >= B || q1 * vn0 > B * rhat + un1 {
        q1 -= 1;
        rhat += vn1;
        if rhat >= B {
            break;
        }
    }
    let un21 = u1.wrapping_mul(B).wrapping_add(un1).wrapping_sub(q1.wrapping_mul(v));
    let mut q0 = un21 / vn1;
    let mut rhat = un21 - q0 * vn1;
    while q0 >= B || q0 * vn0 > B * rhat + un0 {
        q0 -= 1;
        rhat += vn1;
        if rhat >= B {
            break;
        }
    }
    q1.wrapping_mul(B).wrapping_add(q0)
}

/// One step of Knuth's algorithm D with 32-bit digits: the quotient digit and remainder of
/// `a / y` for a normalised 64-bit `y` and `a < y·2³²`. The digit estimate from `divlu` on the
/// top words is at most 2 too large (Knuth, TAOCP 4.3.1, theorem B); the product is formed
/// from two `UMULL`s.
#[inline]
fn divide_step(a: u128, y: u64) -> (u64, u64) {
    let (a2, a1) = ((a >> 64) as u32, (a >> 32) as u32);
    let y1 = (y >> 32) as u32;
    let mut digit = if a2 >= y1 { u32::MAX } else { divlu(a2, a1, y1) };
    let mut product = (u128::from(u64::from(digit) * (y >> 32)) << 32) + u128::from(u64::from(digit) * (y & 0xFFFF_FFFF));
    while product > a {
        digit -= 1;
        product -= u128::from(y);
    }
    (u64::from(digit), (a - product) as u64)
}

/// `a / b` in Q32.32, rounded to nearest (ties away from zero), saturating; `None` for `b == 0`.
///
/// `|a|·2³² / |b|` by Knuth's long division with 32-bit digits on the normalised divisor,
/// each digit estimated with the 32-bit hardware division (two or three `UDIV`s per result
/// instead of a call to the 64- or 128-bit software division).
#[inline]
fn div_q32(a: i64, b: i64) -> Option<i64> {
    if b == 0 {
        return None;
    }
    let negative = (a ^ b) < 0;
    let (x, y) = (a.unsigned_abs(), b.unsigned_abs());
    let limit = if negative { 1u64 << 63 } else { i64::MAX as u64 };
    let saturated = if negative { i64::MIN } else { i64::MAX };
    let shift = y.leading_zeros();
    let (quotient, remainder) = if shift >= 32 {
        // One-digit divisor (|b| < 1). The quotient reaches 2^63 exactly when x ≥ y·2^31.
        if x >= y << 31 {
            return Some(saturated);
        }
        let shift = shift - 32;
        let v = (y << shift) as u32;
        // x·2^(32 + shift) has the digits d2:d1:0 (d3 = 0 and d2 < v, as the quotient < 2^63).
        let n = u128::from(x) << (32 + shift);
        let (d2, d1) = ((n >> 64) as u32, (n >> 32) as u32);
        let q1 = divlu(d2, d1, v);
        let r1 = d1.wrapping_sub(q1.wrapping_mul(v)); // (d2:d1) − q1·v < v
        let q0 = divlu(r1, 0, v);
        let r0 = 0u32.wrapping_sub(q0.wrapping_mul(v));
        ((u64::from(q1) << 32) | u64::from(q0), u64::from(r0) >> shift)
    } else {
        // Two-digit divisor: n = x·2^(32 + shift) < 2^127, quotient < 2^64 in two digits.
        let y_normalised = y << shift;
        let n = u128::from(x) << (32 + shift);
        let (q1, r1) = divide_step(n >> 32, y_normalised);
        let (q0, r0) = divide_step(u128::from(r1) << 32, y_normalised);
        ((q1 << 32) | q0, r0 >> shift)
    };
    // Round half away from zero: remainder ≥ y/2. quotient < 2^64 − 1 here (the divisor's top
    // digit is at least 2^31), so adding 1 cannot overflow.
    let magnitude = quotient + u64::from(remainder >= y - remainder);
    Some(if magnitude > limit {
        saturated
    } else if negative {
        // magnitude = 2^63 only when negative: wrapping_neg gives i64::MIN, exactly right.
        (magnitude as i64).wrapping_neg()
    } else {
        magnitude as i64
    })
}

/// `√(raw·2⁻³²)` in Q32.32 raw bits, for `raw > 0`: `isqrt(raw·2³²)` through a 64-bit integer
/// square root of the normalised value, rounded to nearest (exact to ½ LSB for values below 1,
/// within 2⁻³² relative above).
#[inline]
fn sqrt_q32(raw: i64) -> i64 {
    if raw <= 0 {
        return 0;
    }
    let x = raw as u64;
    let shift = x.leading_zeros() & !1; // even, so the root shifts by whole bits
    // √(x·2^32) = √(x·2^s)·2^((32 − s)/2), with s = 32 when x < 2^32 (exact), otherwise the
    // normalising shift (the root of the normalised value has 32 significant bits).
    let s = shift.min(32);
    let n = x << s;
    let r = n.isqrt(); // < 2^32
    // Round: r + ½ ≤ √n  ⟺  n ≥ r² + r + ¼  ⟺  n > r² + r (integers). r² + r < 2^64.
    let rounded = r + u64::from(n - r * r > r);
    (rounded << ((32 - s) / 2)) as i64
}

/// `bits·2^exponent`: a left shift that saturates instead of losing the top bits, or a right
/// shift rounded to nearest (ties up).
fn shift_bits_i64(bits: i64, exponent: i32) -> i64 {
    if exponent >= 0 {
        let shift = exponent.unsigned_abs();
        match bits.checked_shl(shift) {
            Some(shifted) if shift < 64 && shifted >> shift == bits => shifted,
            _ if bits == 0 => 0,
            _ if bits < 0 => i64::MIN,
            _ => i64::MAX,
        }
    } else {
        let shift = exponent.unsigned_abs().min(63);
        // bits/2^shift rounded: (bits + 2^(shift−1)) >> shift, without overflowing near MAX.
        (bits >> shift) + ((bits >> (shift - 1)) & 1)
    }
}

impl fmt::Debug for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Fixed({})", self.to_f64())
    }
}

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl Add for Fixed {
    type Output = Self;
    #[inline]
    fn add(self, other: Self) -> Self {
        Self::from_bits(self.to_bits().saturating_add(other.to_bits()))
    }
}

impl Sub for Fixed {
    type Output = Self;
    #[inline]
    fn sub(self, other: Self) -> Self {
        Self::from_bits(self.to_bits().saturating_sub(other.to_bits()))
    }
}

impl Mul for Fixed {
    type Output = Self;
    #[inline]
    fn mul(self, other: Self) -> Self {
        Self::from_bits(mul_q32(self.to_bits(), other.to_bits()))
    }
}

impl Neg for Fixed {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::from_bits(self.to_bits().saturating_neg())
    }
}

impl Number for Fixed {
    const NAME: &'static str = "fixed";

    fn write_literal(self, out: &mut dyn core::fmt::Write) -> core::fmt::Result {
        write!(out, "microtrace::number::Fixed::from_bits({})", self.to_bits())
    }
    const FLOATING_POINT: bool = false;
    const RESOLUTION: Self = Self::from_bits(1);
    const SCENE_LIMIT: f64 = Self::COORDINATE_LIMIT;
    const ZERO: Self = Self::from_bits(0);
    const ONE: Self = Self::from_bits(1 << 32);
    const MAX: Self = Self::from_bits(i64::MAX);

    fn from_f64(value: f64) -> Self {
        // `as` saturates and maps NaN to 0.
        Self::from_bits(libm::round(value * ONE_32) as i64)
    }

    fn to_f64(self) -> f64 {
        self.to_bits() as f64 / ONE_32
    }

    fn from_i32(value: i32) -> Self {
        Self::from_bits(i64::from(value) << 32)
    }

    fn sqrt(self) -> Self {
        Self::from_bits(sqrt_q32(self.to_bits()))
    }

    fn checked_div(self, divisor: Self) -> Option<Self> {
        div_q32(self.to_bits(), divisor.to_bits()).map(Self::from_bits)
    }

    fn floor_to_i32(self) -> i32 {
        // An arithmetic shift floors; any i64 shifted right by 32 fits an i32.
        (self.to_bits() >> 32) as i32
    }

    fn times_power_of_two(self, exponent: i32) -> Self {
        Self::from_bits(shift_bits_i64(self.to_bits(), exponent))
    }

    fn binary_exponent(self) -> Option<i32> {
        let magnitude = self.to_bits().unsigned_abs();
        (magnitude != 0).then(|| 63 - magnitude.leading_zeros() as i32 - 32)
    }

    fn abs(self) -> Self {
        Self::from_bits(self.to_bits().saturating_abs())
    }

    /// The three exact 128-bit products summed before one rounding: more accurate than three
    /// rounded products and, on Cortex-M3, about a third of the instructions.
    fn dot3(a: [Self; 3], b: [Self; 3]) -> Self {
        // Each product is at most 2^126 in magnitude, so the sums can overflow only for products
        // far outside the result's range, where saturating gives the right (saturated) result.
        let sum = wide_mul(a[0].to_bits(), b[0].to_bits())
            .saturating_add(wide_mul(a[1].to_bits(), b[1].to_bits()))
            .saturating_add(wide_mul(a[2].to_bits(), b[2].to_bits()));
        Self::from_bits(round_q64(sum))
    }

    /// Pre-scales vectors with a component of 2¹⁴ or more so the squares cannot saturate; the
    /// bits shifted out are below the result's relative precision.
    fn length3(v: [Self; 3]) -> Self {
        let largest = v.iter().map(|c| c.to_bits().unsigned_abs()).max().unwrap_or(0);
        // Components below 2^14 (raw 2^46): the sum of squares is below 3·2^28 < 2^31.
        if largest < 1 << 46 {
            return Self::dot3(v, v).sqrt();
        }
        // Shift right until the largest component is below 2^46 raw, then shift the result back.
        let shift = 64 - largest.leading_zeros() - 46; // 1..=18
        let scaled = v.map(|c| Self::from_bits(c.to_bits() >> shift));
        let length = Self::dot3(scaled, scaled).sqrt().to_bits();
        Self::from_bits(length.checked_shl(shift).filter(|l| l >> shift == length).unwrap_or(i64::MAX))
    }

}

// ---------------------------------------------------------------------------------------------
// Q16.16
// ---------------------------------------------------------------------------------------------

/// Q16.16 fixed point with 64-bit intermediates (see the module docs): cheaper than [`Fixed`],
/// measurably less accurate for this tracer.
#[derive(Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Fixed16(pub I16F16);

/// 2¹⁶: one unit of `Fixed16` in raw bits.
const ONE_16: f64 = 65_536.0;

impl Fixed16 {
    /// The largest magnitude [`Number::can_represent`] accepts: half the range, so a sum or
    /// difference of two such values does not saturate. Squared object-space distances above
    /// 32 767 (distances above 181 radii) still saturate.
    pub const COORDINATE_LIMIT: f64 = 16_384.0;

    pub const fn from_bits(bits: i32) -> Self {
        Self(I16F16::from_bits(bits))
    }

    pub const fn to_bits(self) -> i32 {
        self.0.to_bits()
    }
}

#[inline]
fn saturate_i32(value: i64) -> i32 {
    value.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

/// A Q32.32 `i64` (a product of two Q16.16) rounded to Q16.16 (to nearest, ties up), saturating.
#[inline]
fn round_q32_to_q16(product: i64) -> i32 {
    saturate_i32(product.saturating_add(1 << 15) >> 16)
}

impl fmt::Debug for Fixed16 {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Fixed16({})", self.to_f64())
    }
}

impl fmt::Display for Fixed16 {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl Add for Fixed16 {
    type Output = Self;
    #[inline]
    fn add(self, other: Self) -> Self {
        Self::from_bits(self.to_bits().saturating_add(other.to_bits()))
    }
}

impl Sub for Fixed16 {
    type Output = Self;
    #[inline]
    fn sub(self, other: Self) -> Self {
        Self::from_bits(self.to_bits().saturating_sub(other.to_bits()))
    }
}

impl Mul for Fixed16 {
    type Output = Self;
    #[inline]
    fn mul(self, other: Self) -> Self {
        // |a·b| ≤ 2^62: the i64 product (one SMULL) cannot overflow.
        Self::from_bits(round_q32_to_q16(i64::from(self.to_bits()) * i64::from(other.to_bits())))
    }
}

impl Neg for Fixed16 {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::from_bits(self.to_bits().saturating_neg())
    }
}

impl Number for Fixed16 {
    const NAME: &'static str = "fixed16";
    /// Directions from a far light in steps of 2⁻¹⁶ miss the footprints' margins.
    const SHADOW_CULLING_HOLDS: bool = false;
    /// A depth bound near the type's range (a cube 8000 across) misses by more than its margin.
    const DEPTH_BOUNDS_HOLD: bool = false;

    fn write_literal(self, out: &mut dyn core::fmt::Write) -> core::fmt::Result {
        write!(out, "microtrace::number::Fixed16::from_bits({})", self.to_bits())
    }
    const FLOATING_POINT: bool = false;
    const RESOLUTION: Self = Self::from_bits(1);
    const SCENE_LIMIT: f64 = Self::COORDINATE_LIMIT;
    const ZERO: Self = Self::from_bits(0);
    const ONE: Self = Self::from_bits(1 << 16);
    const MAX: Self = Self::from_bits(i32::MAX);

    fn from_f64(value: f64) -> Self {
        Self::from_bits(libm::round(value * ONE_16) as i32)
    }

    fn to_f64(self) -> f64 {
        f64::from(self.to_bits()) / ONE_16
    }

    fn from_i32(value: i32) -> Self {
        Self::from_bits(saturate_i32(i64::from(value) << 16))
    }

    /// Exact: `⌊√(raw·2¹⁶)⌋` in integers.
    fn sqrt(self) -> Self {
        let raw = self.to_bits();
        if raw <= 0 {
            return Self::ZERO;
        }
        // < 2^47, so the root is < 2^24: no saturation.
        Self::from_bits(((raw as u64) << 16).isqrt() as i32)
    }

    fn checked_div(self, divisor: Self) -> Option<Self> {
        let (a, b) = (i64::from(self.to_bits()), i64::from(divisor.to_bits()));
        if b == 0 {
            return None;
        }
        let negative = (a ^ b) < 0;
        let (x, y) = (a.unsigned_abs() << 16, b.unsigned_abs()); // x < 2^48
        let (q, r) = (x / y, x % y);
        let magnitude = (q + u64::from(r >= y - r)) as i64; // < 2^49
        Some(Self::from_bits(saturate_i32(if negative { -magnitude } else { magnitude })))
    }

    fn floor_to_i32(self) -> i32 {
        self.to_bits() >> 16
    }

    fn times_power_of_two(self, exponent: i32) -> Self {
        Self::from_bits(saturate_i32(shift_bits_i64(i64::from(self.to_bits()), exponent)))
    }

    fn binary_exponent(self) -> Option<i32> {
        let magnitude = self.to_bits().unsigned_abs();
        (magnitude != 0).then(|| 31 - magnitude.leading_zeros() as i32 - 16)
    }

    fn abs(self) -> Self {
        Self::from_bits(self.to_bits().saturating_abs())
    }

    /// Three exact 64-bit products summed before a single rounding.
    fn dot3(a: [Self; 3], b: [Self; 3]) -> Self {
        let product = |i: usize| i64::from(a[i].to_bits()) * i64::from(b[i].to_bits());
        // Each product is ≤ 2^62; if a partial sum saturates, the total is beyond the range of
        // the result anyway, so the saturated result is the right one.
        Self::from_bits(round_q32_to_q16(product(0).saturating_add(product(1)).saturating_add(product(2))))
    }

    /// The exact sum of squares in a `u64` (≤ 3·2⁶²) and its integer square root, which is
    /// already Q16.16: `√(S·2⁻³²) = isqrt(S)·2⁻¹⁶`.
    fn length3(v: [Self; 3]) -> Self {
        let sum: u64 = v.iter().map(|c| {
            let m = u64::from(c.to_bits().unsigned_abs());
            m * m
        }).sum();
        Self::from_bits(sum.isqrt().min(i32::MAX as u64) as i32)
    }

}

#[cfg(test)]
mod tests {
    use super::{Fixed, Fixed16};
    use crate::number::Number;

    /// Scaling by powers of two: exact upward, rounded to nearest downward, saturating at the
    /// ends (never wrapping), and the exponent of the leading bit.
    #[test]
    fn powers_of_two_saturate_and_round() {
        assert_eq!(Fixed::from_f64(1.5).times_power_of_two(3), Fixed::from_i32(12));
        assert_eq!(Fixed::from_bits(3).times_power_of_two(-1), Fixed::from_bits(2));
        assert_eq!(Fixed::from_bits(-3).times_power_of_two(-1), Fixed::from_bits(-1));
        assert_eq!(Fixed::from_i32(3).times_power_of_two(40), Fixed::MAX);
        assert_eq!(Fixed::from_i32(-3).times_power_of_two(40), -Fixed::MAX - Fixed::from_bits(1));
        assert_eq!(Fixed::from_i32(3).times_power_of_two(-200), Fixed::ZERO);
        assert_eq!(Fixed::ZERO.times_power_of_two(100), Fixed::ZERO);
        assert_eq!(Fixed16::from_i32(3).times_power_of_two(20), Fixed16::MAX);
        assert_eq!(Fixed16::from_f64(0.75).times_power_of_two(-1), Fixed16::from_f64(0.375));
        assert_eq!(Fixed::from_f64(0.75).binary_exponent(), Some(-1));
        assert_eq!(Fixed::from_bits(1).binary_exponent(), Some(-32));
        assert_eq!(Fixed::from_f64(-8.0).binary_exponent(), Some(3));
        assert_eq!(Fixed16::from_f64(1e-4).binary_exponent(), Some(-14));
        assert_eq!(Fixed16::ZERO.binary_exponent(), None);
    }
}
