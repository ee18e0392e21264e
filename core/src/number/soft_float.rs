//! A lean software floating point for cores without an FPU (feature `soft-float`):
//! [`SoftFloat`] (`NAME = "soft32"`).
//!
//! A value is `mantissa · 2^(exponent − 27)` with a two's-complement `i32` mantissa whose
//! magnitude lies in [2²⁷, 2²⁸) (28 significant bits, four more than `f32`'s 24) and an `i32`
//! binary exponent in [−1024, 1023] (within `f64`'s range and precision, so every value
//! converts to `f64` exactly). Zero is the mantissa 0 with an exponent far below every other
//! value's. There is no NaN, infinity, negative zero or denormal: a result too large saturates
//! to ±[`Number::MAX`], one too small flushes to zero, and division by zero is `None` (the
//! trait's rules).
//!
//! The three bits of headroom above the mantissa are what make it cheap on a Cortex-M3: a sum
//! of two mantissas with two guard bits, and a sum of three products cut to 29 bits, fit an
//! `i32`, so additions and dot products run in 32-bit registers; a product is one 32×32→64
//! multiply (`SMULL`); normalising is one `CLZ` and a shift, on the two's complement without
//! taking absolute values; division uses the 32-bit `UDIV`. Multiplication, division, square
//! root and the conversions round the exact result to nearest (ties toward +∞ where the
//! mantissa is signed: products and sums; away from zero in division and the conversions).
//! Additions are exact before that rounding when the exponents differ by at most 2 (so
//! `x − y` is exact for `y/2 ≤ x ≤ 2y`, as in IEEE arithmetic) and otherwise faithful: within
//! one unit in the last place, 2⁻²⁷ relative. `dot3` rounds its exact products to 2⁻²⁷ of
//! their size (exact when a factor is a power of two; opposite products cancel exactly) and
//! aligns them before one final rounding: its error is within about 2⁻²⁶ of the largest
//! product, where `f32`'s is within about 2⁻²³.
//!
//! Measured on Cortex-M3 (QEMU lm3s6965evb, instruction-count plugin, `opt-level = "s"`, LTO;
//! per operation including the call where there is one): add/sub about 30 out of line (now
//! always inlined, about 25), mul about 16 (inlined), dot3 about 55 inlined and 71 with the
//! transform's column gathering and call, div 61, sqrt 80. Software `f32` there: add 77,
//! mul 48, dot3 ≈ 320, div 178, sqrt 172 (fixed.rs). Per pixel, snooker at 128x64 with every
//! optimization off: `f32` 84 262, `fixed` 55 413, `soft32` 30 597 instructions.
//!
//! Nothing here can panic: every shift amount is bounded and every intermediate fits its
//! integer type (the comments say why).

use core::cmp::Ordering;
use core::fmt;
use core::ops::{Add, Mul, Neg, Sub};

use super::Number;

/// A software floating-point number: 28-bit mantissa, binary exponent (see the module docs).
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct SoftFloat {
    /// Magnitude in [2²⁷, 2²⁸), or 0 for zero.
    mantissa: i32,
    /// The binary exponent: the value is `mantissa · 2^(exponent − 27)`, so that
    /// `2^exponent ≤ |value| < 2^(exponent + 1)`.
    exponent: i32,
}

/// The bits below the mantissa's leading bit.
const FRACTION_BITS: i32 = 27;
/// The largest exponent: `MAX` is just below 2¹⁰²⁴, still a finite `f64`.
const MAX_EXPONENT: i32 = 1023;
/// The smallest exponent: the smallest positive value is 2⁻¹⁰²⁴, and a mantissa's last bit
/// there (2⁻¹⁰⁵¹) is still above `f64`'s smallest subnormal (2⁻¹⁰⁷⁴). [−1024, 1023] makes the
/// range check one addition and one comparison with an immediate (2048).
const MIN_EXPONENT: i32 = -1024;
/// Zero's exponent, far below every other value's: zero sorts below every positive value when
/// exponents are compared first, an addition aligns it away without a special case, and a
/// product with a zero factor gets an exponent below the range, which flushes it to zero.
const ZERO_EXPONENT: i32 = -4096;
/// The smallest normalised mantissa magnitude, 2²⁷.
const LOWEST_MAGNITUDE: u32 = 1 << FRACTION_BITS;

impl SoftFloat {
    /// The largest magnitude [`Number::can_represent`] accepts: three squares of it
    /// (3·10³⁰⁰) stay below [`Number::MAX`] (about 9·10³⁰⁷).
    pub const COORDINATE_LIMIT: f64 = 1e150;

    /// The value of [`SoftFloat::mantissa`] and [`SoftFloat::exponent`] as written by
    /// `write_literal` (the caller keeps them normalised).
    pub const fn from_parts(mantissa: i32, exponent: i32) -> Self {
        Self { mantissa, exponent }
    }

    /// The mantissa, magnitude in [2²⁷, 2²⁸) (0 for zero).
    pub const fn mantissa(self) -> i32 {
        self.mantissa
    }

    /// The binary exponent (meaningless for zero).
    pub const fn exponent(self) -> i32 {
        self.exponent
    }
}

/// `mantissa · 2^(exponent − 27)` for a mantissa whose magnitude lies in [2²⁷, 2²⁸]: ±2²⁸
/// (a rounding carry, or a negative power of two normalised as two's complement) moves into
/// the exponent; beyond the exponent range the value saturates or flushes to zero.
#[inline(always)]
fn from_signed(mantissa: i32, exponent: i32) -> SoftFloat {
    // ±2^28 are the only allowed inputs that are multiples of 2^29 once 2^28 is added; both
    // they and exponents out of range are rare, so they share one branch to an outlined path.
    let carried = (mantissa + (1 << 28)) & ((1 << 29) - 1) == 0;
    let out_of_range = (exponent - MIN_EXPONENT) as u32 > (MAX_EXPONENT - MIN_EXPONENT) as u32;
    if carried || out_of_range {
        return from_signed_rare(mantissa, exponent);
    }
    SoftFloat { mantissa, exponent }
}

/// [`from_signed`]'s rare cases: a carry to fold into the exponent, an exponent out of range.
#[cold]
#[inline(never)]
fn from_signed_rare(mantissa: i32, exponent: i32) -> SoftFloat {
    let (mantissa, exponent) = if (mantissa + (1 << 28)) & ((1 << 29) - 1) == 0 {
        (mantissa >> 1, exponent + 1) // exact
    } else {
        (mantissa, exponent)
    };
    if exponent < MIN_EXPONENT {
        SoftFloat::ZERO
    } else if exponent > MAX_EXPONENT {
        if mantissa < 0 {
            -SoftFloat::MAX
        } else {
            SoftFloat::MAX
        }
    } else {
        SoftFloat { mantissa, exponent }
    }
}

/// `±rounded · 2^(exponent − 27)` for a magnitude in [2²⁷, 2²⁸] (see [`from_signed`]).
#[inline(always)]
fn from_rounded(negative: bool, rounded: u32, exponent: i32) -> SoftFloat {
    let magnitude = rounded as i32; // ≤ 2^28
    from_signed(if negative { -magnitude } else { magnitude }, exponent)
}

/// `value · 2^(exponent − 31)` for any `i32`, rounded to 28 bits (to nearest, ties toward
/// +∞): the leading bit is moved to bit 27, rounding the bits shifted out when it is above.
/// Works on the two's complement directly, with no absolute value: the leading bit is the
/// first that differs from the sign bit (`CLZ` of `value ^ (value >> 31)`), which for a
/// negative power of two is one place further down, giving the mantissa −2²⁸ that
/// [`from_signed`] folds into the exponent.
#[inline(always)]
fn normalise(value: i32, exponent: i32) -> SoftFloat {
    if value == 0 {
        return SoftFloat::ZERO;
    }
    let leading = (value ^ (value >> 31)).leading_zeros(); // 1..=32: bit 31 of the XOR is 0
    let mantissa = if leading < 4 {
        // Shift right by 1..=3, rounding: ((v >> (s − 1)) + 1) >> 1; |v >> (s − 1)| < 2^30.
        ((value >> (3 - leading)) + 1) >> 1
    } else {
        value << (leading - 4)
    };
    from_signed(mantissa, exponent - leading as i32)
}

/// `(⌊dividend·2²⁴ / divisor⌋, remainder)` for a divisor in [2²⁷, 2²⁸) and a quotient below
/// 2²⁸, from a reciprocal: a 16-bit estimate of 2⁴⁴/divisor by one 32-bit `UDIV` of the
/// divisor's top 16 bits, one Newton step to 2⁵⁶/divisor (error ε → ε², 2⁻¹⁵ → 2⁻³⁰: within 3
/// units), the quotient from one `UMULL` by it (within 4), and a correction by the remainder.
/// (Goldschmidt and Newton–Raphson division: Muller et al., Handbook of Floating-Point
/// Arithmetic, 2nd ed., §4.5, §5.3.)
#[inline]
fn divide_by_reciprocal(dividend: u32, divisor: u32) -> (u32, u32) {
    // The top 16 bits, at least 2^15 (setting that bit again tells the compiler it is not
    // zero, so the division needs no check).
    let top = (divisor >> 12) | (1 << 15);
    // 2^44/divisor·(1 + ε) with 0 ≤ ε < 2^−15 + 2^−16: top·2^12 ≤ divisor < (top + 1)·2^12.
    let estimate = u32::MAX / top; // (2^16, 2^17]
    // 2^44 − divisor·estimate = −2^44·ε: |error| < 2^30.
    let error = ((1i64 << 44) - i64::from(divisor) * i64::from(estimate)) as i32;
    // estimate·2^12·(1 − ε) = 2^56/divisor·(1 − ε²), less the floor of the correction: within
    // 3 units below 2^56/divisor ≤ 2^29.
    let correction = ((i64::from(estimate) * i64::from(error)) >> 32) as i32;
    let reciprocal = (estimate << 12).wrapping_add(correction as u32);
    // dividend·reciprocal/2^32 is within 4 of the quotient (dividend < 2^32).
    let mut quotient = ((u64::from(dividend) * u64::from(reciprocal)) >> 32) as u32;
    // The remainder of that estimate lies within ±4 divisors (below 2^31), so the low words of
    // dividend·2^24 and quotient·divisor give it exactly.
    let mut remainder = (dividend << 24).wrapping_sub(quotient.wrapping_mul(divisor)) as i32;
    let divisor = divisor as i32;
    while remainder < 0 {
        quotient -= 1;
        remainder += divisor;
    }
    while remainder >= divisor {
        quotient += 1;
        remainder -= divisor;
    }
    (quotient, remainder as u32)
}

/// `⌊√radicand⌋` for a radicand in [2⁵⁴, 2⁵⁶): a 16-bit root of the radicand's top 32 bits
/// by Newton's method in 32-bit arithmetic, one Newton step at full width whose division is two
/// 32-bit `UDIV`s, and a final correction by comparing squares.
#[inline]
fn integer_square_root(radicand: u64) -> u64 {
    let top = (radicand >> 24) as u32; // [2^30, 2^32)
    // A first estimate within 5 % of √top ∈ [2^15, 2^16): the tangent at 2^31,
    // √(2^31)/2 + top/(2√(2^31)), with the division by 92 682 as shifts (top/95 325).
    let mut root = (top >> 17) + (top >> 19) + (top >> 20) + 23_170;
    // Integer Newton steps: after the first the estimate is at least ⌊√top⌋ and the relative
    // error squares (5 % → 1.2·10⁻³ → 7·10⁻⁷): within one unit of √top. No overflow: the
    // estimate stays below 2^17 and top/root below 2^17.
    root = (root + top / root) >> 1;
    root = (root + top / root) >> 1;
    // One step at full width from s = root·2^12 ≈ √radicand (relative error ≤ 2^−15):
    // (s + radicand/s)/2, within one unit of the root. radicand/s = (radicand >> 12)/root, a
    // 44-bit dividend over a 16-bit divisor: two 32-bit divisions with 16-bit digits (the
    // remainder < root ≤ 2^16 keeps the second dividend below 2^32).
    let dividend = radicand >> 12; // < 2^44
    let upper = (dividend >> 16) as u32; // < 2^28
    let quotient_high = upper / root;
    let remainder = upper - quotient_high * root;
    let quotient_low = ((remainder << 16) | (dividend as u32 & 0xFFFF)) / root;
    let quotient = (u64::from(quotient_high) << 16) + u64::from(quotient_low);
    let mut result = ((u64::from(root) << 12) + quotient) >> 1;
    // result < 2^29, so its square fits u64; each loop runs at most a few times.
    while result * result > radicand {
        result -= 1;
    }
    while (result + 1) * (result + 1) <= radicand {
        result += 1;
    }
    result
}

impl fmt::Debug for SoftFloat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "SoftFloat({:?})", self.to_f64())
    }
}

impl fmt::Display for SoftFloat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.to_f64(), f)
    }
}

impl Default for SoftFloat {
    /// Zero (a derived default would not be the canonical zero).
    fn default() -> Self {
        Self::ZERO
    }
}

impl Ord for SoftFloat {
    #[inline]
    fn cmp(&self, other: &Self) -> Ordering {
        if self.exponent == other.exponent {
            // Same binade (or both zero): the signed mantissas decide.
            return self.mantissa.cmp(&other.mantissa);
        }
        // The one with the larger exponent has the larger magnitude (zero's exponent is the
        // lowest, so it is never that one): its sign decides.
        let (larger, sign) = if self.exponent > other.exponent { (self, Ordering::Greater) } else { (other, Ordering::Less) };
        if larger.mantissa > 0 {
            sign
        } else {
            sign.reverse()
        }
    }
}

impl PartialOrd for SoftFloat {
    #[inline]
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Add for SoftFloat {
    type Output = Self;
    /// Always inlined: the call would cost a quarter of the addition (measured on the M3: 2.4 %
    /// fewer instructions per pixel on snooker, 3.4 % on the lattice, 4 KB more flash).
    #[inline(always)]
    fn add(self, other: Self) -> Self {
        // Both exponents lie in [ZERO_EXPONENT, MAX_EXPONENT]: no overflow. Two straight paths
        // by the sign of the difference are cheaper than swapping the operands first.
        let difference = self.exponent - other.exponent;
        if difference >= 0 {
            if difference > 29 {
                return self;
            }
            aligned_sum(self, other, difference as u32)
        } else {
            if difference < -29 {
                return other;
            }
            aligned_sum(other, self, difference.unsigned_abs())
        }
    }
}

/// `larger + smaller` for `larger.exponent − smaller.exponent = difference` in 0..=29.
///
/// Beyond 29 the smaller addend is below 2^(larger.exponent − 29), a quarter of larger's last
/// place, so larger itself is the sum rounded to nearest (also at a power of two, where the
/// spacing below is half): the caller returns it. Zero has the lowest exponent and is always
/// dropped there unless both operands are tiny.
#[inline(always)]
fn aligned_sum(larger: SoftFloat, smaller: SoftFloat, difference: u32) -> SoftFloat {
    // Both mantissas with two guard bits (below 2^30 each, so the sum is below 2^31), the
    // smaller one shifted into place: exact when difference ≤ 2, otherwise its bits below the
    // guard bits are cut (rounded toward −∞), less than a quarter of a unit in the last place
    // before the final rounding.
    let sum = (larger.mantissa << 2) + ((smaller.mantissa << 2) >> difference);
    // sum · 2^(larger.exponent − 27 − 2) = sum · 2^((larger.exponent + 2) − 31).
    normalise(sum, larger.exponent + 2)
}

impl Sub for SoftFloat {
    type Output = Self;
    /// Always inlined, as the addition.
    #[inline(always)]
    fn sub(self, other: Self) -> Self {
        self + -other
    }
}

impl Mul for SoftFloat {
    type Output = Self;
    #[inline]
    fn mul(self, other: Self) -> Self {
        // One SMULL: the exact product, magnitude in [2^54, 2^56), or 0.
        let product = i64::from(self.mantissa) * i64::from(other.mantissa);
        // product · 2^(self.exponent + other.exponent − 54): round off 28 bits when the
        // magnitude is 2^55 or more (the top word, sign bits flipped, says so; −2^55 itself
        // takes the other branch and carries), otherwise 27. Both give [−2^28, −2^27] or
        // [2^27, 2^28]. A zero factor's exponent puts the sum far below the range, which
        // flushes the product to zero.
        let high = (product >> 32) as i32;
        let exponent = self.exponent + other.exponent;
        let (rounded, exponent) = if (high ^ (high >> 31)) >= 1 << 23 {
            (((product + (1 << 27)) >> 28) as i32, exponent + 1)
        } else {
            (((product + (1 << 26)) >> 27) as i32, exponent)
        };
        from_signed(rounded, exponent)
    }
}

impl Neg for SoftFloat {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        // The mantissa's magnitude is below 2^28: no overflow.
        Self { mantissa: -self.mantissa, exponent: self.exponent }
    }
}

impl Number for SoftFloat {
    const NAME: &'static str = "soft32";

    fn write_literal(self, out: &mut dyn core::fmt::Write) -> core::fmt::Result {
        write!(out, "microtrace::number::SoftFloat::from_parts({}, {})", self.mantissa, self.exponent)
    }
    const SCENE_LIMIT: f64 = Self::COORDINATE_LIMIT;
    // Relative precision, and scaling by a power of two (an exponent change) is exact: the
    // fixed-point rescaling would change no result.
    const FLOATING_POINT: bool = true;
    const RESOLUTION: Self = Self::ZERO;
    const ZERO: Self = Self { mantissa: 0, exponent: ZERO_EXPONENT };
    const ONE: Self = Self { mantissa: LOWEST_MAGNITUDE as i32, exponent: 0 };
    /// Not zero (zero's exponent is `ZERO_EXPONENT`): only a placeholder, never computed with.
    const ZEROED: Self = Self { mantissa: 0, exponent: 0 };
    const MAX: Self = Self { mantissa: (2 * LOWEST_MAGNITUDE - 1) as i32, exponent: MAX_EXPONENT };

    fn from_f64(value: f64) -> Self {
        if value.is_nan() || value == 0.0 {
            return Self::ZERO;
        }
        if value.is_infinite() {
            return if value < 0.0 { -Self::MAX } else { Self::MAX };
        }
        // value = fraction · 2^exponent with |fraction| in [0.5, 1); fraction · 2^28 is exact
        // and rounds to [2^27, 2^28].
        let (fraction, exponent) = libm::frexp(value);
        let rounded = libm::round(libm::fabs(fraction) * f64::from(1u32 << (FRACTION_BITS + 1))) as u32;
        // rounded · 2^(exponent − 28) = rounded · 2^((exponent − 1) − 27).
        from_rounded(value < 0.0, rounded, exponent - 1)
    }

    fn to_f64(self) -> f64 {
        // Exact: 28 bits whose lowest is at 2^(exponent − 27) ≥ 2^−1051, above f64's subnormal
        // step 2^−1074.
        libm::scalbn(f64::from(self.mantissa), self.exponent - FRACTION_BITS)
    }

    fn from_i32(value: i32) -> Self {
        // value = value · 2^(31 − 31).
        normalise(value, 31)
    }

    /// Correctly rounded (to nearest, ties away from zero).
    fn sqrt(self) -> Self {
        if self.mantissa <= 0 {
            return Self::ZERO;
        }
        // value = m · 2^(e − 27). With k = 27 or 28 so that e − 27 − k is even,
        // √value = √(m · 2^k) · 2^((e − 27 − k)/2), where m · 2^k lies in [2^54, 2^56) and its
        // root in [2^27, 2^28): already a mantissa, with the exponent e >> 1 (floor).
        let shift = FRACTION_BITS as u32 + (self.exponent & 1) as u32;
        let radicand = u64::from(self.mantissa as u32) << shift;
        let root = integer_square_root(radicand);
        // Round: root + ½ ≤ √radicand ⟺ radicand > root² + root (integers).
        let rounded = (root + u64::from(radicand - root * root > root)) as u32;
        from_rounded(false, rounded, self.exponent >> 1)
    }

    fn checked_div(self, divisor: Self) -> Option<Self> {
        if divisor.mantissa == 0 {
            return None;
        }
        if self.mantissa == 0 {
            return Some(Self::ZERO);
        }
        let negative = (self.mantissa ^ divisor.mantissa) < 0;
        let (dividend, divisor_magnitude) = (self.mantissa.unsigned_abs(), divisor.mantissa.unsigned_abs());
        // The dividend scaled so that the quotient lies in [2^27, 2^28): dividend·2^27 when the
        // ratio is in [1, 2), dividend·2^28 when it is in (½, 1), as (dividend·2^3 or ·2^4)·2^24.
        let exponent = self.exponent - divisor.exponent;
        let (scaled, exponent) = if dividend >= divisor_magnitude { (dividend << 3, exponent) } else { (dividend << 4, exponent - 1) };
        let (quotient, remainder) = divide_by_reciprocal(scaled, divisor_magnitude);
        // Round half away from zero: remainder ≥ divisor/2.
        let rounded = quotient + u32::from(remainder >= divisor_magnitude - remainder);
        Some(from_rounded(negative, rounded, exponent))
    }

    fn floor_to_i32(self) -> i32 {
        if self.exponent < 0 {
            // |value| < 1 (or zero): 0, or −1 below zero.
            return if self.mantissa < 0 { -1 } else { 0 };
        }
        if self.exponent > 30 {
            // |value| ≥ 2^31: saturate (−2^31 itself is i32::MIN, the saturated value anyway).
            return if self.mantissa < 0 { i32::MIN } else { i32::MAX };
        }
        if self.exponent <= FRACTION_BITS {
            // An arithmetic shift floors; the shift is 0..=27.
            self.mantissa >> (FRACTION_BITS - self.exponent)
        } else {
            // An integer: |mantissa| < 2^28 shifted by 1..=3 stays below 2^31.
            self.mantissa << (self.exponent - FRACTION_BITS)
        }
    }

    fn times_power_of_two(self, exponent: i32) -> Self {
        if self.mantissa == 0 {
            return self;
        }
        // Clamped far beyond the range first, so that nothing after can overflow.
        let exponent = self.exponent + exponent.clamp(-4 * MAX_EXPONENT, 4 * MAX_EXPONENT);
        from_rounded(self.mantissa < 0, self.mantissa.unsigned_abs(), exponent)
    }

    fn binary_exponent(self) -> Option<i32> {
        (self.mantissa != 0).then_some(self.exponent)
    }

    #[inline]
    fn abs(self) -> Self {
        Self { mantissa: self.mantissa.abs(), exponent: self.exponent }
    }

    /// The three products, each exact (`SMULL`) and then rounded to 29 bits, aligned and summed
    /// in an `i32`, then rounded once: one normalisation instead of five, all in 32-bit
    /// registers.
    /// Inlined where LLVM sees fit: the callers gather columns into arrays, which inlining
    /// turns into registers.
    #[inline]
    fn dot3(a: [Self; 3], b: [Self; 3]) -> Self {
        // product · 2^(exponent − 54) with |product| in [2^54, 2^56) (or 0), rounded to
        // product / 2^27 (half up: opposite products round to opposite terms, so they cancel
        // exactly, as in IEEE arithmetic): at most 2^29 in magnitude, and exact when a factor
        // is a power of two. Kept as product / 2^26 plus one (below 2^30 + 1), whose halving
        // completes the rounding and joins the alignment shift below. A product with a zero
        // factor is 0 with an exponent below any non-zero product's.
        let term = |i: usize| {
            let product = i64::from(a[i].mantissa) * i64::from(b[i].mantissa);
            (((product >> (FRACTION_BITS - 1)) as i32) + 1, a[i].exponent + b[i].exponent)
        };
        let (first, second, third) = (term(0), term(1), term(2));
        let largest = first.1.max(second.1).max(third.1);
        // Halved and aligned to the largest exponent in one shift (cutting the bits shifted
        // out, below 2^−27 of the largest product); three terms below 2^29 sum below 2^31.
        // Products with a zero factor, common in axis-aligned transforms, have shifts far above
        // 31, so each shift is clamped: clamp(0, 31) of the positive shift is one USAT.
        let aligned = |(value, exponent): (i32, i32)| value >> (largest + 1 - exponent).clamp(0, 31);
        let sum = aligned(first) + aligned(second) + aligned(third);
        // sum · 2^(largest − 27) = sum · 2^((largest + 4) − 31).
        normalise(sum, largest + 4)
    }
}

#[cfg(test)]
mod tests;
