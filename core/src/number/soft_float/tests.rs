//! `SoftFloat` against `f64`: every operand is exactly an `f64` (31 significant bits), so the
//! `f64` result of one operation is the exact result to 2⁻⁵³, and a correctly rounded
//! `SoftFloat` result is within half a unit in its last place: 2⁻²⁸ relative.

extern crate std;

use std::format;
use std::vec::Vec;

use super::{divide_by_reciprocal, integer_square_root, SoftFloat, MAX_EXPONENT, MIN_EXPONENT};
use crate::number::Number;
use core::cmp::Ordering;

/// Half a unit in the last place, relative (2⁻²⁸), with room for the `f64` reference's own
/// rounding.
const HALF_UNIT: f64 = 3.725_290_298_461_914e-9 * (1.0 + 1e-6);

/// xorshift64*: deterministic operands without a dependency.
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A random value with a random sign, 28 random significant bits and an exponent in
    /// ±`exponent_range`; now and then a zero or a short mantissa (exact cases).
    fn soft_float(&mut self, exponent_range: i32) -> SoftFloat {
        let bits = self.next();
        let exponent = (bits % (2 * exponent_range as u64 + 1)) as i32 - exponent_range;
        let mut magnitude = (1u32 << 27) | (bits >> 36) as u32 & ((1 << 27) - 1);
        match bits & 15 {
            0 => return SoftFloat::ZERO,
            1 => magnitude &= !((1 << 17) - 1), // 11 significant bits
            2 => magnitude = 1 << 27,           // a power of two
            _ => {}
        }
        let mantissa = if bits & 16 != 0 { -(magnitude as i32) } else { magnitude as i32 };
        SoftFloat { mantissa, exponent }
    }
}

fn soft(value: f64) -> SoftFloat {
    SoftFloat::from_f64(value)
}

fn assert_close(result: SoftFloat, exact: f64, context: &str) {
    let error = (result.to_f64() - exact).abs();
    assert!(error <= HALF_UNIT * exact.abs(), "{context}: {result:?} against {exact:e} (relative error {:e})", error / exact.abs());
}

fn assert_canonical(value: SoftFloat) {
    let magnitude = value.mantissa.unsigned_abs();
    assert!(
        value == SoftFloat::ZERO || ((1 << 27)..(1 << 28)).contains(&magnitude) && (MIN_EXPONENT..=MAX_EXPONENT).contains(&value.exponent),
        "{value:?} is not normalised: {:?}",
        (value.mantissa, value.exponent)
    );
}

#[test]
fn arithmetic_is_correctly_rounded() {
    let mut random = Random(0x9E37_79B9_7F4A_7C15);
    for _ in 0..200_000 {
        let (a, b) = (random.soft_float(60), random.soft_float(60));
        let (x, y) = (a.to_f64(), b.to_f64());
        let context = format!("{a:?}, {b:?}");
        for result in [a + b, a - b, a * b, a.sqrt()] {
            assert_canonical(result);
        }
        assert_close(a * b, x * y, &format!("product of {context}"));
        // Sums are exact in f64 (53 bits) unless the exponents are more than 25 apart; then
        // f64's own rounding (2⁻⁵³) is within the margin.
        let difference = (a.exponent - b.exponent).abs();
        if difference <= 2 || x == 0.0 || y == 0.0 {
            // Exact before one rounding.
            assert_close(a + b, x + y, &format!("sum of {context}"));
            assert_close(a - b, x - y, &format!("difference of {context}"));
        } else {
            // Faithful: below one unit in the last place.
            for (result, exact) in [(a + b, x + y), (a - b, x - y)] {
                let error = (result.to_f64() - exact).abs();
                assert!(error <= 2.0 * HALF_UNIT * exact.abs(), "sum or difference of {context}: {result:?} against {exact:e}");
            }
        }
        match a.checked_div(b) {
            None => assert_eq!(y, 0.0),
            Some(quotient) => {
                assert_canonical(quotient);
                assert_close(quotient, x / y, &format!("quotient of {context}"));
            }
        }
        assert_close(a.sqrt(), if x > 0.0 { libm::sqrt(x) } else { 0.0 }, &format!("root of {a:?}"));
    }
}

#[test]
fn dot_products_round_once() {
    let mut random = Random(42);
    for _ in 0..100_000 {
        let a = [0; 3].map(|_| random.soft_float(20));
        let b = [0; 3].map(|_| random.soft_float(20));
        let products = [0, 1, 2].map(|i| a[i].to_f64() * b[i].to_f64());
        let exact = products[0] + products[1] + products[2];
        let largest = products.iter().fold(0.0f64, |m, p| m.max(p.abs()));
        let result = SoftFloat::dot3(a, b);
        assert_canonical(result);
        // Rounded once, from three products and two aligned terms each cut below 2⁻²⁷ of the
        // largest product.
        let error = (result.to_f64() - exact).abs();
        assert!(error <= HALF_UNIT * exact.abs() + 5.0 * 2f64.powi(-27) * largest, "dot3 of {a:?}, {b:?}: {result:?} against {exact:e}");
        let length = SoftFloat::length3(a).to_f64();
        let exact_length = a.iter().map(|c| c.to_f64() * c.to_f64()).sum::<f64>();
        let exact_length = libm::sqrt(exact_length);
        assert!((length - exact_length).abs() <= 4.0 * HALF_UNIT * exact_length, "length of {a:?}");
    }
}

#[test]
fn small_integers_are_exact() {
    for a in -40..=40 {
        for b in -40..=40 {
            let (x, y) = (SoftFloat::from_i32(a), SoftFloat::from_i32(b));
            assert_eq!(x + y, SoftFloat::from_i32(a + b));
            assert_eq!(x - y, SoftFloat::from_i32(a - b));
            assert_eq!(x * y, SoftFloat::from_i32(a * b));
            if b != 0 && a % b == 0 {
                assert_eq!(x.checked_div(y), Some(SoftFloat::from_i32(a / b)));
            }
        }
        assert_eq!(SoftFloat::from_i32(a * a).sqrt(), SoftFloat::from_i32(a.abs()));
        assert_eq!(SoftFloat::from_i32(a).to_f64(), f64::from(a));
    }
    assert_eq!(soft(0.75).sqrt() * soft(0.75).sqrt(), soft(0.75).sqrt().powi(2));
    assert_eq!(soft(0.25).sqrt(), soft(0.5));
    assert_eq!(soft(1.0).checked_div(soft(3.0)).map(SoftFloat::to_f64), Some(soft(1.0 / 3.0).to_f64()));
    assert_eq!(SoftFloat::from_i32(i32::MIN).to_f64(), f64::from(i32::MIN));
    // 2³¹ − 1 has 31 significant bits: rounded to 28.
    assert_eq!(SoftFloat::from_i32(i32::MAX).to_f64(), 2_147_483_648.0);
    assert_eq!(SoftFloat::from_i32((1 << 28) - 1).to_f64(), f64::from((1 << 28) - 1));
}

#[test]
fn conversions_round_trip_and_round() {
    let mut random = Random(7);
    for _ in 0..10_000 {
        let value = random.soft_float(1000);
        assert_eq!(soft(value.to_f64()), value);
    }
    assert_eq!(soft(1.0), SoftFloat::ONE);
    assert_eq!(soft(-0.0), SoftFloat::ZERO);
    assert_eq!(soft(f64::NAN), SoftFloat::ZERO);
    // 1 + 2⁻²⁸ is a tie between 1 and 1 + 2⁻²⁷: away from zero.
    assert_eq!(soft(1.0 + 2f64.powi(-28)).to_f64(), 1.0 + 2f64.powi(-27));
    assert_eq!(soft(1.0 + 2f64.powi(-29)).to_f64(), 1.0);
    // Rounding up to the next power of two carries into the exponent.
    assert_eq!(soft(2.0 - 2f64.powi(-29)), soft(2.0));
    assert_eq!(soft(f64::MAX), SoftFloat::MAX);
    assert_eq!(soft(f64::NEG_INFINITY), -SoftFloat::MAX);
    assert_eq!(soft(1e-310), SoftFloat::ZERO);
    assert!(SoftFloat::MAX.to_f64().is_finite());
}

#[test]
fn extremes_saturate_and_flush_to_zero() {
    let max = SoftFloat::MAX;
    let tiny = soft(2f64.powi(MIN_EXPONENT));
    assert_eq!(max + max, max);
    assert_eq!(-max - max, -max);
    assert_eq!(max * soft(2.0), max);
    assert_eq!(max * -max, -max);
    assert_eq!(max.checked_div(soft(0.5)), Some(max));
    assert_eq!(soft(-1e300).checked_div(soft(1e-300)), Some(-max));
    assert_eq!(max - max, SoftFloat::ZERO);
    assert_eq!(tiny * soft(0.5), SoftFloat::ZERO);
    assert_eq!(tiny * tiny, SoftFloat::ZERO);
    assert_eq!(tiny.checked_div(soft(3.0)), Some(SoftFloat::ZERO));
    assert_eq!(tiny.times_power_of_two(-1), SoftFloat::ZERO);
    assert_eq!(soft(3.0).times_power_of_two(i32::MAX), max);
    assert_eq!(soft(-3.0).times_power_of_two(i32::MIN), SoftFloat::ZERO);
    assert_eq!(SoftFloat::dot3([max; 3], [max; 3]), max);
    assert_eq!(SoftFloat::dot3([max, -max, max], [max; 3]), max);
    assert_eq!(SoftFloat::length3([max; 3]), max.sqrt());
    assert_eq!(soft(0.9).powi(100_000), SoftFloat::ZERO);
    // tiny + tiny is 2·tiny; tiny − tiny·(1 + 2⁻²⁷) is below the range.
    assert_eq!(tiny + tiny, tiny.times_power_of_two(1));
    assert_eq!(tiny - soft(2f64.powi(MIN_EXPONENT) * (1.0 + 2f64.powi(-27))), SoftFloat::ZERO);
}

#[test]
fn zero_and_signs() {
    let zero = SoftFloat::ZERO;
    let x = soft(-2.5);
    assert_eq!(zero + x, x);
    assert_eq!(x + zero, x);
    assert_eq!(x - x, zero);
    assert_eq!(x * zero, zero);
    assert_eq!(zero * x, zero);
    assert_eq!(-zero, zero);
    assert_eq!(zero.checked_div(x), Some(zero));
    assert_eq!(x.checked_div(zero), None);
    assert_eq!(zero.checked_div(zero), None);
    assert_eq!(x.sqrt(), zero);
    assert_eq!(zero.sqrt(), zero);
    assert_eq!(x.abs(), soft(2.5));
    assert_eq!(-x, soft(2.5));
    assert_eq!(x * x, soft(6.25));
    assert_eq!(x * -x, soft(-6.25));
    assert_eq!(x.checked_div(soft(-0.5)), Some(soft(5.0)));
    assert_eq!(SoftFloat::dot3([zero; 3], [x; 3]), zero);
    assert_eq!(SoftFloat::dot3([x, -x, zero], [x, x, SoftFloat::MAX]), zero);
    assert_eq!(SoftFloat::default(), zero);
}

#[test]
fn comparisons_match_the_values() {
    let mut random = Random(3);
    let samples: Vec<SoftFloat> = (0..2_000).map(|_| random.soft_float(3)).collect();
    for a in &samples {
        for b in &samples[..200] {
            let expected = a.to_f64().partial_cmp(&b.to_f64()).unwrap();
            assert_eq!(a.cmp(b), expected, "{a:?} against {b:?}");
            assert_eq!(a.partial_cmp(b), Some(expected));
            assert_eq!(a == b, expected == Ordering::Equal);
        }
    }
    assert!(SoftFloat::ZERO < SoftFloat::ONE && -SoftFloat::ONE < SoftFloat::ZERO);
    assert!(-SoftFloat::MAX < soft(-1e300) && soft(1e-300) > SoftFloat::ZERO);
    assert_eq!(Number::min(soft(2.0), soft(-3.0)), soft(-3.0));
    assert_eq!(Number::max(soft(2.0), soft(-3.0)), soft(2.0));
}

#[test]
fn floor_powers_of_two_and_exponents() {
    for value in [0.0, 0.5, -0.5, 1.0, -1.0, 2.75, -2.75, 1e9, -1e9, 2147483647.0, -2147483648.0, 3e9, -3e9, 1e-300, -1e-300, 1e300] {
        assert_eq!(soft(value).floor_to_i32(), value.floor() as i32, "{value}");
    }
    assert_eq!(soft(2147483647.5).floor_to_i32(), i32::MAX);
    assert_eq!(soft(3.0).times_power_of_two(-2), soft(0.75));
    assert_eq!(soft(-3.0).times_power_of_two(10), soft(-3072.0));
    assert_eq!(SoftFloat::ZERO.times_power_of_two(5), SoftFloat::ZERO);
    assert_eq!(soft(0.75).binary_exponent(), Some(-1));
    assert_eq!(soft(-8.0).binary_exponent(), Some(3));
    assert_eq!(SoftFloat::ZERO.binary_exponent(), None);
    assert!(SoftFloat::can_represent(1e150) && !SoftFloat::can_represent(1e151) && !SoftFloat::can_represent(f64::NAN));
}

#[test]
fn integer_square_roots_are_floors() {
    let mut random = Random(11);
    let check = |radicand: u64| assert_eq!(integer_square_root(radicand), radicand.isqrt(), "{radicand}");
    for radicand in [1 << 54, (1 << 54) + 1, (1 << 55) - 1, 1 << 55, (1 << 56) - 1, ((1 << 28) - 1) * ((1 << 28) - 1)] {
        check(radicand);
    }
    for _ in 0..200_000 {
        let radicand = (1 << 54) + random.next() % (3 << 54);
        check(radicand);
        // Perfect squares and their neighbours.
        let root = radicand.isqrt();
        for candidate in [root * root, root * root - 1, root * root + 1] {
            if ((1 << 54)..(1 << 56)).contains(&candidate) {
                check(candidate);
            }
        }
    }
}

#[test]
fn mantissa_division_is_exact() {
    let mut random = Random(5);
    let check = |dividend: u32, divisor: u32| {
        let numerator = u64::from(dividend) << 24;
        let expected = ((numerator / u64::from(divisor)) as u32, (numerator % u64::from(divisor)) as u32);
        assert_eq!(divide_by_reciprocal(dividend, divisor), expected, "{dividend} / {divisor}");
    };
    // The divisor in [2^27, 2^28); the dividend as checked_div scales it (·2^3 when at least the
    // divisor, ·2^4 when below), so the quotient is below 2^28.
    let edges = [1 << 27, (1 << 27) + 1, (1 << 27) + (1 << 12) - 1, (1 << 27) + (1 << 12), 3 << 26, (1 << 28) - (1 << 12), (1 << 28) - 1];
    for &divisor in &edges {
        for &dividend in &edges {
            check(if dividend >= divisor { dividend << 3 } else { dividend << 4 }, divisor);
        }
    }
    for _ in 0..1_000_000 {
        let bits = random.next();
        let divisor = (1 << 27) | (bits as u32 & ((1 << 27) - 1));
        let dividend = (1 << 27) | ((bits >> 32) as u32 & ((1 << 27) - 1));
        check(if dividend >= divisor { dividend << 3 } else { dividend << 4 }, divisor);
    }
}
