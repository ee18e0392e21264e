//! Real roots of a polynomial of degree up to four on an interval, by bracketing, in any number
//! type: the roots of the derivative split the interval into stretches where the polynomial is
//! monotone; a stretch whose ends differ in sign holds exactly one root, which Newton steps
//! find, kept inside the bracket (a step that leaves it is replaced by halving the bracket).
//! Nothing here can miss a root between two that cancel or divide by a vanishing derivative,
//! the failures of closed-form quartic solvers (Ferrari's, in POV-Ray and Graphics Gems) on
//! grazing rays and far or scaled tori. Only `+ − × ÷`, one square root and comparisons, so it
//! works in fixed point as in floating point.
//!
//! A touching (double) root shows as a critical point where the polynomial is exactly zero; one
//! where rounding leaves it a hair above zero is a miss, as a quadric's zero discriminant is a
//! hit and a negative one a miss.

use crate::number::Number;

/// Bracket steps at most: each halves the bracket at least every other step, and 64 halvings
/// take any interval the torus gives (< 8 units) below the resolution of every number type.
const MAX_STEPS: u32 = 64;

/// `c[0] + c[1]·u + … + c[K−1]·u^(K−1)` by Horner's rule.
#[inline]
fn value<N: Number, const K: usize>(c: &[N; K], u: N) -> N {
    let mut sum = N::ZERO;
    for coefficient in c.iter().rev() {
        sum = sum * u + *coefficient;
    }
    sum
}

/// The sign of `v`: −1, 0 or 1.
#[inline]
fn sign<N: Number>(v: N) -> i8 {
    if v > N::ZERO {
        1
    } else if v < N::ZERO {
        -1
    } else {
        0
    }
}

/// The one root in `[lo, hi]` of a polynomial `f` (coefficients `c`, derivative `dc`) that is
/// monotone there, with `f(lo)` and `f(hi)` of opposite signs (neither zero).
fn monotone_root<N: Number, const K: usize, const D: usize>(c: &[N; K], dc: &[N; D], lo: N, hi: N, f_lo: N) -> N {
    let (mut lo, mut hi) = (lo, hi);
    let lo_sign = sign(f_lo);
    let mut x = lo;
    let mut f_x = f_lo;
    for _ in 0..MAX_STEPS {
        let middle = lo + (hi - lo).times_power_of_two(-1);
        let step = f_x.checked_div(value(dc, x)).map(|ratio| x - ratio);
        let next = match step {
            Some(next) if next > lo && next < hi => next,
            _ => middle,
        };
        if next == x || middle == lo || middle == hi {
            break;
        }
        x = next;
        f_x = value(c, x);
        match sign(f_x) {
            0 => return x,
            s if s == lo_sign => lo = x,
            _ => hi = x,
        }
    }
    x
}

/// The roots of the quadratic `c` in `[lo, hi]`, ascending (stable form, one square root); a
/// double root once.
fn quadratic_roots<N: Number>(c: &[N; 3], lo: N, hi: N) -> ([N; 2], usize) {
    let mut found = [N::ZERO; 2];
    let mut count: usize = 0;
    let (a, b, k) = (c[2], c[1], c[0]);
    // `get`, not indexing: no panic path in the firmware's image.
    let mut push = |root: N| {
        if root >= lo && root <= hi && count.checked_sub(1).and_then(|last| found.get(last)).copied() != Some(root) {
            if let Some(slot) = found.get_mut(count) {
                *slot = root;
                count += 1;
            }
        }
    };
    if a == N::ZERO {
        if let Some(root) = (-k).checked_div(b) {
            push(root);
        }
        return (found, count);
    }
    let discriminant = b * b - (a * k).times_power_of_two(2);
    if discriminant < N::ZERO {
        return (found, count);
    }
    let root_of = discriminant.sqrt();
    let q = if b < N::ZERO { (-b + root_of).times_power_of_two(-1) } else { (-b - root_of).times_power_of_two(-1) };
    let mut pair = [q.checked_div(a), k.checked_div(q)];
    if let [Some(x), Some(y)] = pair {
        if y < x {
            pair = [Some(y), Some(x)];
        }
    }
    for root in pair.into_iter().flatten() {
        push(root);
    }
    (found, count)
}

/// The real roots in `[lo, hi]` of the quartic `c[0] + c[1] u + … + c[4] u⁴` (`c[4] > 0`),
/// ascending, each once, the first `limit` of them (a nearest hit needs one or two, CSG's spans
/// all four); the count is how many are found. The quartic's critical points (its derivative's
/// roots) are found in order as the walk needs them, so a walk that stops early finds no more
/// of them than it used.
pub fn quartic_roots<N: Number>(c: &[N; 5], lo: N, hi: N, limit: usize) -> ([N; 4], usize) {
    let cubic = [c[1], c[2].times_power_of_two(1), c[3] * N::from_i32(3), c[4].times_power_of_two(2)];
    let quadratic = [cubic[1], cubic[2].times_power_of_two(1), cubic[3] * N::from_i32(3)];
    let (bends, bend_count) = quadratic_roots(&quadratic, lo, hi);
    let mut walk = Walk::new(c, &cubic, lo, limit);
    // The cubic's roots, piece by piece between the quadratic's: each ends a monotone stretch
    // of the quartic.
    let (mut start, mut f_start) = (lo, value(&cubic, lo));
    for end in bends.iter().take(bend_count).copied().chain(core::iter::once(hi)) {
        if walk.done() {
            break;
        }
        if end <= start {
            continue;
        }
        let f_end = value(&cubic, end);
        match (sign(f_start), sign(f_end)) {
            (_, 0) => walk.to(end),
            (0, _) => {}
            (a, b) if a != b => walk.to(monotone_root(&cubic, &quadratic, start, end, f_start)),
            _ => {}
        }
        start = end;
        f_start = f_end;
    }
    walk.to(hi);
    (walk.found, walk.count)
}

/// The walk along the quartic from one critical point to the next, collecting its roots.
struct Walk<'a, N> {
    c: &'a [N; 5],
    dc: &'a [N; 4],
    start: N,
    f_start: N,
    limit: usize,
    found: [N; 4],
    count: usize,
}

impl<'a, N: Number> Walk<'a, N> {
    fn new(c: &'a [N; 5], dc: &'a [N; 4], lo: N, limit: usize) -> Self {
        let mut walk = Self { c, dc, start: lo, f_start: value(c, lo), limit, found: [N::ZERO; 4], count: 0 };
        if walk.f_start == N::ZERO {
            walk.push(lo);
        }
        walk
    }

    fn done(&self) -> bool {
        self.count >= self.limit
    }

    // `get`, not indexing: no panic path in the firmware's image.
    fn push(&mut self, root: N) {
        if self.count.checked_sub(1).and_then(|last| self.found.get(last)).copied() != Some(root) {
            if let Some(slot) = self.found.get_mut(self.count) {
                *slot = root;
                self.count += 1;
            }
        }
    }

    /// The stretch from the last critical point to `end`, where the quartic is monotone.
    fn to(&mut self, end: N) {
        if self.done() || end <= self.start {
            return;
        }
        let f_end = value(self.c, end);
        match (sign(self.f_start), sign(f_end)) {
            (_, 0) => self.push(end),
            (0, _) => {}
            (a, b) if a != b => {
                let root = monotone_root(self.c, self.dc, self.start, end, self.f_start);
                self.push(root);
            }
            _ => {}
        }
        self.start = end;
        self.f_start = f_end;
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;

    /// `(u − a)(u − b)(u − c)(u − d)` as coefficients.
    fn from_roots(roots: [f64; 4]) -> [f64; 5] {
        let mut c = [1.0, 0.0, 0.0, 0.0, 0.0];
        for (degree, root) in roots.into_iter().enumerate() {
            // Multiply the polynomial of degree `degree` by (u − root).
            for i in (0..=degree + 1).rev() {
                let shifted = if i > 0 { c[i - 1] } else { 0.0 };
                c[i] = shifted - root * if i <= degree { c[i] } else { 0.0 };
            }
        }
        c
    }

    fn roots(c: [f64; 5], lo: f64, hi: f64) -> Vec<f64> {
        let (found, count) = quartic_roots(&c, lo, hi, 4);
        found[..count].to_vec()
    }

    #[test]
    fn four_simple_roots_in_order() {
        let found = roots(from_roots([3.75, 4.25, 5.75, 6.25]), 0.0, 10.0);
        assert_eq!(found.len(), 4, "{found:?}");
        for (got, want) in found.iter().zip([3.75, 4.25, 5.75, 6.25]) {
            assert!((got - want).abs() < 1e-12, "{found:?}");
        }
    }

    #[test]
    fn only_the_roots_inside_the_interval() {
        let found = roots(from_roots([-1.0, 0.5, 2.0, 9.0]), 0.0, 3.0);
        assert_eq!(found.len(), 2, "{found:?}");
        assert!((found[0] - 0.5).abs() < 1e-12 && (found[1] - 2.0).abs() < 1e-12, "{found:?}");
    }

    #[test]
    fn touching_roots_grazing_in_and_out() {
        // (u − 1)² (u − 3)(u − 4): touching at 1. Whether the touch itself counts is rounding's
        // call (the critical point is found to within rounding, where f is ≥ 0); if it does,
        // it is one root, at 1.
        let found = roots(from_roots([1.0, 1.0, 3.0, 4.0]), 0.0, 2.0);
        assert!(found.len() <= 1 && found.iter().all(|root| (root - 1.0).abs() < 1e-6), "{found:?}");
        // Lowered a little: two roots either side of 1 (√(1e−9 / 6) away).
        let mut lowered = from_roots([1.0, 1.0, 3.0, 4.0]);
        lowered[0] -= 1e-9;
        let found = roots(lowered, 0.0, 2.0);
        assert_eq!(found.len(), 2, "{found:?}");
        let half_gap = (1e-9f64 / 6.0).sqrt();
        assert!((found[0] - (1.0 - half_gap)).abs() < 1e-8 && (found[1] - (1.0 + half_gap)).abs() < 1e-8, "{found:?}");
        // Lifted a little: no real root near 1.
        let mut lifted = from_roots([1.0, 1.0, 3.0, 4.0]);
        lifted[0] += 1e-9;
        assert!(roots(lifted, 0.0, 2.0).is_empty());
    }

    #[test]
    fn no_real_roots() {
        // u⁴ + 1.
        assert!(roots([1.0, 0.0, 0.0, 0.0, 1.0], -5.0, 5.0).is_empty());
    }

    #[test]
    fn close_pairs_are_separated() {
        // Pairs 1e−6 apart: the rounding of f (about 1e−13 here) moves each root by its size over
        // the slope there (about 1e−5), so to within 1e−8 or so; both of each pair are found.
        let found = roots(from_roots([2.0, 2.0 + 1e-6, 5.0, 5.0 + 1e-6]), 0.0, 8.0);
        assert_eq!(found.len(), 4, "{found:?}");
        for (got, want) in found.iter().zip([2.0, 2.0 + 1e-6, 5.0, 5.0 + 1e-6]) {
            assert!((got - want).abs() < 1e-7, "{found:?}");
        }
    }
}
