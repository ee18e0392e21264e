//! Sortlist (§4.7.5): objects ordered by a lower bound of the ray parameter `t` of any hit, so
//! the loop can stop once the next object's bound exceeds the nearest hit so far.
//!
//! The thesis sorted by the largest world z and was right only for rays toward −z (digest B5).
//! Here the bound is in `t` itself, which is correct for every view direction:
//! - parallel: the ray from view-plane point o along unit d reaches p at t = (p.z − D)/d.z, so
//!   the bound is that linear function's minimum over the volume (exact for a sphere's
//!   ellipsoid); with d.z = 0, t = d·p − d·o, bounded with the window corner maximising d·o;
//! - perspective: t is the distance from the eye (unit directions), bounded below by the
//!   largest signed distance to the volume's face planes (and for a sphere by
//!   |eye − centre| minus its largest semi-axis); for a volume reaching the eye plane also by
//!   its clip depth ε: a ray reaches it only at depth ≥ ε, so t ≥ ε·|D − eye.z|.
//!
//! Bounds are computed in `f64` and lowered by a margin before conversion, so rounding in the
//! number type cannot make an object's computed `t` fall below its bound. The loop breaks only
//! when the bound is strictly greater than the nearest `t`: an equal `t` may still win the tie
//! for a lower object number.

use super::bounding_volume::{dot, largest_semi_axis, ObjectGeometry, View};
use super::projection::Screen;
use crate::config::Config;
use crate::storage::Index;

/// The lower bound of `t` for one object (already lowered by the rounding margin); `None` when
/// no bound is known (the object is then tested first and never ends the loop).
pub fn depth_bound(screen: &Screen, corners: &[[f64; 3]; 4], geometry: &ObjectGeometry) -> Option<f64> {
    let bound = match screen.view {
        View::Parallel { direction: d } => {
            if d[2].abs() > 1e-6 {
                let g = [0.0, 0.0, 1.0 / d[2]];
                geometry.min_linear(g) - screen.view_plane / d[2]
            } else {
                let origin_max = corners.iter().map(|o| dot(*o, d)).fold(f64::NEG_INFINITY, f64::max);
                geometry.min_linear(d) - origin_max
            }
        }
        View::Perspective { eye } => {
            let bound = geometry.distance_lower_bound(eye);
            // A volume reaching the eye plane is seen only beyond its clip depth (B16).
            let volume = geometry.volume();
            let reaches = volume.iter().any(|p| screen.project(*p).is_none());
            match reaches.then(|| screen.clip_depth(&volume, geometry)).flatten() {
                Some(depth) if depth.is_finite() => bound.max(depth * (screen.view_plane - eye[2]).abs()),
                _ => bound,
            }
        }
    };
    bound.is_finite().then(|| bound - 1e-3 * (bound.abs() + 1.0))
}

/// An upper bound of `t` over the object's bounding volume: the far end of the depth range
/// whose near end is [`depth_bound`], for display only (the thesis's `zfar`, which it computed
/// and never used; the renderer does not use this either). Parallel: the largest value of the
/// same linear function (exact over a sphere's ellipsoid); perspective: the largest distance
/// from the eye (over the ellipsoid for a sphere, the volume's vertices otherwise). `None` for
/// parallel rays along the view plane.
pub fn far_depth_bound(screen: &Screen, geometry: &ObjectGeometry) -> Option<f64> {
    let bound = match screen.view {
        View::Parallel { direction: d } => {
            if d[2].abs() <= 1e-6 {
                return None;
            }
            -geometry.min_linear([0.0, 0.0, -1.0 / d[2]]) - screen.view_plane / d[2]
        }
        View::Perspective { eye } => match geometry.ellipsoid() {
            Some((centre, m)) => {
                let offset = [0, 1, 2].map(|k| centre[k] - eye[k]);
                libm::sqrt(dot(offset, offset)) + largest_semi_axis(&m)
            }
            None => geometry
                .volume()
                .iter()
                .map(|p| {
                    let offset = [0, 1, 2].map(|k| p[k] - eye[k]);
                    libm::sqrt(dot(offset, offset))
                })
                .fold(0.0, f64::max),
        },
    };
    bound.is_finite().then_some(bound)
}

/// Below this many items a sort is an insertion sort (few comparisons on the short, nearly
/// sorted lists of the thesis's scenes); from it on, a heapsort (n·log n for Haines' 10,000).
pub const INSERTION_SORT_BELOW: usize = 64;

/// Sorts `order` (object numbers, each at most once) by `bound`, ties by object number:
/// from the identity order, the same order as a stable sort. Items whose bound is NaN keep no
/// particular place. No allocation. A build whose `C` holds fewer objects than the heapsort
/// needs links only the insertion sort.
pub fn sort_by_bound<C: Config, T: PartialOrd + Copy>(order: &mut [C::Index], bound: impl Fn(usize) -> T) {
    if C::MAX_OBJECTS < INSERTION_SORT_BELOW || order.len() < INSERTION_SORT_BELOW {
        for i in 1..order.len() {
            let mut j = i;
            while j > 0 && bound(order[j].get()) < bound(order[j - 1].get()) {
                order.swap(j, j - 1);
                j -= 1;
            }
        }
        return;
    }
    let key = |order: &[C::Index], at: usize| {
        let object = order.get(at).map_or(usize::MAX, |object| object.get());
        (bound(object), object)
    };
    #[allow(clippy::neg_cmp_op_on_partial_ord, reason = "`!(b < a)`: equal, or unordered (a NaN), then by object number")]
    let before = |a: (T, usize), b: (T, usize)| a.0 < b.0 || (!(b.0 < a.0) && a.1 < b.1);
    let len = order.len();
    heapsort(order, len, |order, i, j| before(key(order, i), key(order, j)), |order, i, j| {
        if i < order.len() && j < order.len() {
            order.swap(i, j);
        }
    });
}

/// Heapsort of the first `len` items of `items`, reached by position: `less(items, i, j)`
/// compares the items now at `i` and `j`, `swap(items, i, j)` exchanges them. In place, n·log n
/// comparisons, no recursion. Not stable: `less` breaks ties itself where the order of equal
/// items matters.
pub fn heapsort<S: ?Sized>(items: &mut S, len: usize, less: impl Fn(&S, usize, usize) -> bool, swap: impl Fn(&mut S, usize, usize)) {
    // Sift the item at `root` down the heap of the first `end` items.
    let sift = |items: &mut S, mut root: usize, end: usize| loop {
        let mut child = 2 * root + 1;
        if child >= end {
            break;
        }
        if child + 1 < end && less(items, child, child + 1) {
            child += 1;
        }
        if !less(items, root, child) {
            break;
        }
        swap(items, root, child);
        root = child;
    };
    for root in (0..len / 2).rev() {
        sift(items, root, len);
    }
    for end in (1..len).rev() {
        swap(items, 0, end);
        sift(items, 0, end);
    }
}

/// A lower bound of `t` for the part of a cylinder or cone seen through a block of pixels
/// (columns and rows inclusive): the object lies within `radius` of its axis, so an axis point
/// can matter only if it is within `radius` of each of the planes bounding the rays through the
/// block (widened by the projection margin); the bound is the nearest such axis point's `t`
/// less the radius. `None` for other primitives or when no bound is found. Lowered for
/// rounding like [`depth_bound`].
pub fn block_depth_bound(screen: &Screen, geometry: &ObjectGeometry, columns: (u16, u16), rows: (u16, u16)) -> Option<f64> {
    if !geometry.primitive.has_axis() {
        return None;
    }
    let (a, b, radius) = geometry.bounding_capsule();
    let m = super::projection::MARGIN + 0.01;
    let low = screen.to_view_plane(f64::from(columns.0) - m, f64::from(rows.1) + m);
    let high = screen.to_view_plane(f64::from(columns.1) + m, f64::from(rows.0) - m);
    let ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    // Constraints g·p + k ≥ 0 on the points seen through the block.
    let mut constraints = [([0.0; 3], 0.0); 5];
    let depth_of: [f64; 3];
    let mut depth_offset = 0.0;
    let slack: f64;
    match screen.view {
        View::Perspective { eye: e } => {
            let span = screen.view_plane - e[2];
            if span == 0.0 {
                return None;
            }
            // X(p) ≥ low.x ⟺ (p.x − e.x) − (low.x − e.x)(p.z − e.z)/span ≥ 0, and so on.
            let f = |x: f64, axis: usize, sign: f64| {
                let mut g = [0.0; 3];
                g[axis] = sign;
                g[2] = -sign * (x - e[axis]) / span;
                (g, -dot(g, e))
            };
            constraints[0] = f(low[0], 0, 1.0);
            constraints[1] = f(high[0], 0, -1.0);
            constraints[2] = f(low[1], 1, 1.0);
            constraints[3] = f(high[1], 1, -1.0);
            let sign = if span > 0.0 { 1.0 } else { -1.0 };
            constraints[4] = ([0.0, 0.0, sign], -sign * e[2]);
            depth_of = e;
            slack = radius;
        }
        View::Parallel { direction: d } => {
            if d[2].abs() < 1e-6 {
                return None;
            }
            // X(p) = p.x − (d.x/d.z)(p.z − D) ≥ low.x, and so on; t(p) = (p.z − D)/d.z.
            let f = |x: f64, axis: usize, sign: f64| {
                let mut g = [0.0; 3];
                g[axis] = sign;
                g[2] = -sign * d[axis] / d[2];
                (g, sign * (d[axis] / d[2] * screen.view_plane - x))
            };
            constraints[0] = f(low[0], 0, 1.0);
            constraints[1] = f(high[0], 0, -1.0);
            constraints[2] = f(low[1], 1, 1.0);
            constraints[3] = f(high[1], 1, -1.0);
            constraints[4] = constraints[0];
            depth_of = [0.0, 0.0, 1.0 / d[2]];
            depth_offset = -screen.view_plane / d[2];
            slack = radius / d[2].abs();
        }
    }
    // The range of s ∈ [0, 1] on the axis a + s·ab meeting every relaxed constraint.
    let (mut s_low, mut s_high) = (0.0f64, 1.0f64);
    for (g, k) in constraints {
        let norm = libm::sqrt(dot(g, g));
        let (value, rate) = (dot(g, a) + k + radius * norm, dot(g, ab));
        if rate == 0.0 {
            if value < 0.0 {
                return Some(f64::MAX);
            }
        } else if rate > 0.0 {
            s_low = s_low.max(-value / rate);
        } else {
            s_high = s_high.min(-value / rate);
        }
    }
    if s_low.partial_cmp(&s_high).is_none_or(|order| order.is_gt()) {
        return Some(f64::MAX);
    }
    let nearest = match screen.view {
        View::Perspective { .. } => {
            let e = depth_of;
            let squared = dot(ab, ab);
            let s = if squared > 0.0 { within(dot([e[0] - a[0], e[1] - a[1], e[2] - a[2]], ab) / squared, s_low, s_high) } else { s_low };
            let p = [a[0] + s * ab[0], a[1] + s * ab[1], a[2] + s * ab[2]];
            let v = [p[0] - e[0], p[1] - e[1], p[2] - e[2]];
            libm::sqrt(dot(v, v))
        }
        View::Parallel { .. } => {
            let at = |s: f64| dot(depth_of, [a[0] + s * ab[0], a[1] + s * ab[1], a[2] + s * ab[2]]) + depth_offset;
            at(s_low).min(at(s_high))
        }
    };
    let bound = nearest - slack;
    bound.is_finite().then(|| bound - 1e-3 * (bound.abs() + 1.0))
}

/// `value.clamp(low, high)` for `low <= high` (checked by the caller), without `f64::clamp`'s
/// panic, whose message would link float formatting (about 10 KB) into the firmware.
fn within(value: f64, low: f64, high: f64) -> f64 {
    if value < low {
        low
    } else if value > high {
        high
    } else {
        value
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::{heapsort, sort_by_bound, INSERTION_SORT_BELOW};

    /// A small linear congruential generator: the same numbers on every machine.
    fn numbers(seed: u64, count: usize) -> Vec<u64> {
        let mut state = seed;
        (0..count)
            .map(|_| {
                state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                state >> 33
            })
            .collect()
    }

    /// Both sides of the switch to the heapsort, bounds with many ties: the order equals a
    /// stable sort of the identity by bound, as the insertion sort's did.
    #[test]
    fn sorting_by_bound_equals_a_stable_sort_ties_by_object_number() {
        for (seed, count) in [(1, 0), (2, 1), (3, 7), (4, INSERTION_SORT_BELOW - 1), (5, INSERTION_SORT_BELOW), (6, 300), (7, 5_000)] {
            for distinct in [3, 1_000_000] {
                let bounds: Vec<f64> = numbers(seed, count).iter().map(|n| (n % distinct) as f64 - 2.0).collect();
                let mut order: Vec<u16> = (0..count as u16).collect();
                sort_by_bound::<crate::config::Arrays<f64, 5_000>, _>(&mut order, |index| bounds[index]);
                let mut expected: Vec<u16> = (0..count as u16).collect();
                expected.sort_by(|a, b| bounds[usize::from(*a)].total_cmp(&bounds[usize::from(*b)]));
                assert_eq!(order, expected, "{count} bounds, {distinct} distinct");
            }
        }
    }

    #[test]
    fn heapsort_sorts_and_keeps_every_item() {
        for (seed, count) in [(11, 0), (12, 1), (13, 2), (14, 100), (15, 1_001)] {
            let mut items = numbers(seed, count);
            let mut expected = items.clone();
            expected.sort_unstable();
            heapsort(&mut items[..], count, |items: &[u64], i, j| items[i] < items[j], |items: &mut [u64], i, j| items.swap(i, j));
            assert_eq!(items, expected);
        }
    }
}
