//! The ring torus the thesis proposes (§5.2.1): the circle of radius 1 about +z in the plane
//! z = 0, swept by a tube of radius `tube` (0 < tube < 1), so the points where
//! `(|p|² + 1 − tube²)² = 4 (x² + y²)`.
//!
//! A ray meets it at the real roots of a quartic, where textbook solvers fail: roots off by ±0.1
//! on unit shapes scaled to 1e7 (POV-Ray PR 358), a hit outside the torus for a ray that starts
//! inside the tube (brepkit PR 1068), grazing rays (double roots) and rays along the axis. So:
//! - the ray is first clipped to the torus's box, `[−1−tube, 1+tube]² × [−tube, tube]`, and
//!   nothing is solved for a ray that misses it;
//! - the quartic is written about the point where the ray enters the box (or its origin, when
//!   that is inside), in the distance along the normalised direction: its coefficients are then
//!   of the size of the torus, whatever the ray's origin and the object's scale;
//! - its roots are bracketed and polished (`polynomial::quartic_roots`: Newton inside brackets
//!   that the derivative's roots make, bisection where Newton would leave them).
//!
//! `all_crossings` gives every surface crossing in order (the spans CSG needs: a torus has at
//! most two); `intersect` and `occluded` the nearest and any inside the interval, as for the
//! quadrics, from the first two crossings in front (the rest are not looked for). Besides the
//! box, the ray is clipped to the sphere of radius 1 + tube that holds the torus.

use super::hit::Hit;
use super::polynomial;
use super::ScaledInterval;
use crate::geometry::{Ray, Vector3};
use crate::number::Number;

/// The ray parameters where the ray crosses the torus's surface, ascending, and how many there
/// are (0 to 4). Only crossings at `t ≥ 0` and inside the box are looked for. (The tests'
/// view; the tracer asks for the nearest two, CSG for all at any `t`.)
#[cfg(test)]
fn crossings<N: Number>(ray: &Ray<N>, tube: N) -> ([N; 4], usize) {
    crossings_from(ray, tube, N::ZERO, 4)
}

/// The first two crossings at `t ≥ 0`: the nearest hit is the first, or the second when the
/// first is at `t = 0` exactly (a ray from the surface), which the interval leaves out.
fn nearest_crossings<N: Number>(ray: &Ray<N>, tube: N) -> ([N; 4], usize) {
    crossings_from(ray, tube, N::ZERO, 2)
}

/// Every crossing at any `t` (behind the origin too), ascending, with the outward normal (for
/// CSG's spans).
pub fn all_crossings<N: Number>(ray: &Ray<N>, tube: N) -> [Option<(N, Vector3<N>)>; 4] {
    let (roots, count) = crossings_from(ray, tube, -N::MAX, 4);
    let mut found = [None; 4];
    for (slot, t) in found.iter_mut().zip(roots.into_iter().take(count)) {
        *slot = Some((t, normal(ray.at(t), tube)));
    }
    found
}

/// The first `limit` crossings at `t ≥ from`, ascending.
fn crossings_from<N: Number>(ray: &Ray<N>, tube: N, from: N, limit: usize) -> ([N; 4], usize) {
    let none = ([N::ZERO; 4], 0);
    let Some((enter, leave)) = box_span(ray, tube, from) else { return none };
    let d = ray.direction.to_array();
    let length = N::length3(d);
    let Some(unit) = unit_direction(d, length) else { return none };
    // About the entry point, in distance along the unit direction: u ∈ [0, (leave − enter)·|d|].
    let start = ray.at(enter).to_array();
    let span = (leave - enter) * length;
    // Within the sphere of radius 1 + tube about the centre too (the torus's farthest points
    // are on it; widened by 2⁻¹² to stay outside rounding): most rays that cross the box's
    // corners miss it, and those that do not have a shorter stretch to bracket.
    let Some((near, far)) = sphere_span(start, unit, N::ONE + tube) else { return none };
    let (low, high) = (near.max(N::ZERO), far.min(span));
    if low > high {
        return none;
    }
    let coefficients = quartic(start, unit, tube);
    let (roots, count) = polynomial::quartic_roots(&coefficients, low, high, limit);
    let mut found = [N::ZERO; 4];
    let mut kept = 0;
    for u in roots.into_iter().take(count) {
        if let (Some(along), Some(slot)) = (u.checked_div(length), found.get_mut(kept)) {
            *slot = enter + along;
            kept += 1;
        }
    }
    (found, kept)
}

pub fn intersect<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>, tube: N) -> Option<Hit<N>> {
    let (roots, count) = nearest_crossings(ray, tube);
    let t = roots.into_iter().take(count).find(|t| interval.contains(*t))?;
    Some(Hit { t, normal: normal(ray.at(t), tube) })
}

pub fn occluded<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>, tube: N) -> bool {
    let (roots, count) = nearest_crossings(ray, tube);
    roots.into_iter().take(count).any(|t| interval.contains(t))
}

/// The outward normal at a point of the surface, not normalised: the gradient over 4,
/// `(|p|² + 1 − tube²)·p − 2·(x, y, 0)`.
pub fn normal<N: Number>(p: Vector3<N>, tube: N) -> Vector3<N> {
    let sum = N::dot3(p.to_array(), p.to_array()) + N::ONE - tube * tube;
    let two = N::ONE.times_power_of_two(1);
    Vector3::new(p.x * (sum - two), p.y * (sum - two), p.z * sum)
}

/// The ray's parameters inside the torus's box, from `max(entry, from)` to the exit; `None` when
/// it misses the box or leaves it before `from`. A direction component that is zero never
/// divides: the ray is then inside that slab or misses it.
fn box_span<N: Number>(ray: &Ray<N>, tube: N, from: N) -> Option<(N, N)> {
    let reach = N::ONE + tube;
    let half_widths = [reach, reach, tube];
    let (origin, direction) = (ray.origin.to_array(), ray.direction.to_array());
    let mut enter = from;
    let mut leave = N::MAX;
    for axis in 0..3 {
        let (p, d, half) = (origin[axis], direction[axis], half_widths[axis]);
        if d == N::ZERO {
            if p < -half || p > half {
                return None;
            }
            continue;
        }
        let (Some(near), Some(far)) = ((-half - p).checked_div(d), (half - p).checked_div(d)) else { return None };
        let (near, far) = if near <= far { (near, far) } else { (far, near) };
        enter = enter.max(near);
        leave = leave.min(far);
    }
    (enter <= leave).then_some((enter, leave))
}

/// Where `start + u·unit` (`|unit| = 1`) is within `radius` (widened by 2⁻¹²) of the origin:
/// `u² + 2bu + |start|² − r² = 0`, `b = start·unit`; `None` when it never is.
fn sphere_span<N: Number>(start: [N; 3], unit: [N; 3], radius: N) -> Option<(N, N)> {
    let widened = radius + radius.times_power_of_two(-12);
    let b = N::dot3(start, unit);
    let c = N::dot3(start, start) - widened * widened;
    let discriminant = b * b - c;
    if discriminant < N::ZERO {
        return None;
    }
    let root = discriminant.sqrt();
    Some((-b - root, -b + root))
}

/// `d / |d|`, or `None` for a zero direction.
fn unit_direction<N: Number>(d: [N; 3], length: N) -> Option<[N; 3]> {
    Some([d[0].checked_div(length)?, d[1].checked_div(length)?, d[2].checked_div(length)?])
}

/// The coefficients (constant first) of `f(u) = (|p|² + 1 − tube²)² − 4 (x² + y²)` along
/// `p = start + u·unit`, `|unit| = 1`: with `g = |start|² + 1 − tube²` and `b = start·unit`,
/// `|p|² + 1 − tube² = u² + 2bu + g`, so
/// `f = u⁴ + 4b u³ + (4b² + 2g − 4(ux² + uy²)) u² + (4bg − 8(sx ux + sy uy)) u + g² − 4(sx² + sy²)`.
fn quartic<N: Number>(start: [N; 3], unit: [N; 3], tube: N) -> [N; 5] {
    let g = N::dot3(start, start) + N::ONE - tube * tube;
    let b = N::dot3(start, unit);
    let flat_unit = unit[0] * unit[0] + unit[1] * unit[1];
    let flat_cross = start[0] * unit[0] + start[1] * unit[1];
    let flat_start = start[0] * start[0] + start[1] * start[1];
    [
        g * g - flat_start.times_power_of_two(2),
        (b * g).times_power_of_two(2) - flat_cross.times_power_of_two(3),
        (b * b - flat_unit).times_power_of_two(2) + g.times_power_of_two(1),
        b.times_power_of_two(2),
        N::ONE,
    ]
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::shapes::Interval;

    const TUBE: f64 = 0.25;

    fn ray<N: Number>(origin: [f64; 3], direction: [f64; 3]) -> Ray<N> {
        Ray { origin: Vector3::from_f64(origin), direction: Vector3::from_f64(direction) }
    }

    fn roots<N: Number>(origin: [f64; 3], direction: [f64; 3]) -> Vec<f64> {
        let (found, count) = crossings(&ray::<N>(origin, direction), N::from_f64(TUBE));
        found[..count].iter().map(|t| t.to_f64()).collect()
    }

    fn nearest<N: Number>(origin: [f64; 3], direction: [f64; 3]) -> Option<(f64, [f64; 3])> {
        let interval = ScaledInterval { interval: Interval::unbounded(), exponent: 0 };
        intersect(&ray::<N>(origin, direction), interval, N::from_f64(TUBE)).map(|hit| (hit.t.to_f64(), hit.normal.to_f64()))
    }

    /// Every number type the core has, with the tolerance its resolution allows on a unit torus.
    fn in_every_type(check: impl Fn(&dyn Fn([f64; 3], [f64; 3]) -> Vec<f64>, f64)) {
        check(&roots::<f64>, 1e-12);
        check(&roots::<f32>, 2e-5);
        #[cfg(feature = "fixed-point")]
        check(&roots::<crate::number::Fixed>, 1e-6);
        #[cfg(feature = "soft-float")]
        check(&roots::<crate::number::SoftFloat>, 1e-5);
    }

    fn close(found: &[f64], want: &[f64], tolerance: f64) -> bool {
        found.len() == want.len() && found.iter().zip(want).all(|(a, b)| (a - b).abs() <= tolerance * b.abs().max(1.0))
    }

    #[test]
    fn a_ray_through_the_middle_crosses_four_times() {
        in_every_type(|roots, tolerance| {
            let found = roots([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
            assert!(close(&found, &[3.75, 4.25, 5.75, 6.25], tolerance), "{found:?}");
        });
    }

    #[test]
    fn a_ray_down_the_axis_passes_through_the_hole() {
        in_every_type(|roots, _| assert!(roots([0.0, 0.0, 5.0], [0.0, 0.0, -1.0]).is_empty()));
    }

    #[test]
    fn a_ray_from_inside_the_tube_leaves_by_the_tube_wall() {
        // From the tube's centre circle straight up: out through z = tube at t = 0.25, and the
        // hit is on the surface, not beyond it (brepkit PR 1068).
        in_every_type(|roots, tolerance| {
            let found = roots([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
            assert!(close(&found, &[0.25], tolerance), "{found:?}");
            // Along the tube's centre line's tangent: leaves at x² + y² = (1 + tube)², y = √(1.25² − 1).
            let found = roots([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
            assert!(close(&found, &[(1.25f64 * 1.25 - 1.0).sqrt()], tolerance), "{found:?}");
        });
        let (t, normal) = nearest::<f64>([1.0, 0.0, 0.0], [0.0, 0.0, 2.0]).unwrap();
        assert!((t - 0.125).abs() < 1e-12, "{t}");
        assert!(normal[2] > 0.0 && normal[0].abs() < 1e-12 && normal[1].abs() < 1e-12, "{normal:?}");
    }

    #[test]
    fn a_huge_torus_is_hit_where_a_unit_one_is() {
        // A torus scaled by 1e7, seen from 5e7 away: in object space the direction is 1e−7 and
        // the parameters 1e7 times the unit case (POV-Ray PR 358: roots off by ±0.1).
        let found = roots::<f64>([-5.0, 0.0, 0.0], [1e-7, 0.0, 0.0]);
        assert!(close(&found, &[3.75e7, 4.25e7, 5.75e7, 6.25e7], 1e-12), "{found:?}");
        let found = roots::<f32>([-5.0, 0.0, 0.0], [1e-7, 0.0, 0.0]);
        assert!(close(&found, &[3.75e7, 4.25e7, 5.75e7, 6.25e7], 2e-5), "{found:?}");
        // And from far away along an oblique line through the tube's centre at (1, 0, 0).
        let found = roots::<f64>([-3999.0, 0.0, 3e3], [4.0, 0.0, -3.0]);
        assert_eq!(found.len(), 2, "{found:?}");
        for t in found {
            let p = [-3999.0 + 4.0 * t, 0.0, 3e3 - 3.0 * t];
            let residual = (p[0] * p[0] + p[2] * p[2] + 1.0 - TUBE * TUBE).powi(2) - 4.0 * p[0] * p[0];
            assert!(residual.abs() < 1e-9, "{t}: residual {residual}");
        }
    }

    #[test]
    fn grazing_rays_touch_or_miss_cleanly() {
        // Along the top of the tube (z = tube): touches it at x = ±1. Just below: four roots in
        // two close pairs; just above: none.
        in_every_type(|roots, _| {
            let below = roots([-5.0, 0.0, TUBE - 1e-3], [1.0, 0.0, 0.0]);
            assert_eq!(below.len(), 4, "{below:?}");
            assert!(below[1] - below[0] < 0.1 && below[3] - below[2] < 0.1, "{below:?}");
            assert!(roots([-5.0, 0.0, TUBE + 1e-3], [1.0, 0.0, 0.0]).is_empty());
        });
        let touching = roots::<f64>([-5.0, 0.0, TUBE], [1.0, 0.0, 0.0]);
        assert!(touching.len() <= 4 && touching.iter().all(|t| (t - 4.0).abs() < 1e-6 || (t - 6.0).abs() < 1e-6), "{touching:?}");
    }

    #[test]
    fn a_ray_from_the_surface_finds_the_far_side() {
        // From the outer equator inward: through the tube (out at x = 0.75), across the hole and
        // through the other side.
        let found = roots::<f64>([1.25, 0.0, 0.0], [-1.0, 0.0, 0.0]);
        let beyond: Vec<f64> = found.into_iter().filter(|t| *t > 1e-9).collect();
        assert!(close(&beyond, &[0.5, 2.0, 2.5], 1e-12), "{beyond:?}");
        // Outward: nothing in front.
        let outward: Vec<f64> = roots::<f64>([1.25, 0.0, 0.0], [1.0, 0.0, 0.0]).into_iter().filter(|t| *t > 1e-9).collect();
        assert!(outward.is_empty(), "{outward:?}");
    }

    #[test]
    fn behind_the_origin_and_outside_the_interval_is_no_hit() {
        assert!(roots::<f64>([5.0, 0.0, 0.0], [1.0, 0.0, 0.0]).is_empty());
        let r = ray::<f64>([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let below = |max: f64| ScaledInterval { interval: Interval::below(max), exponent: 0 };
        assert!(!occluded(&r, below(3.7), TUBE));
        assert!(occluded(&r, below(3.8), TUBE));
        assert_eq!(intersect(&r, below(3.8), TUBE).map(|hit| hit.t), Some(3.75));
    }

    #[test]
    fn the_normal_points_out_of_the_tube() {
        let n = normal(Vector3::new(1.25, 0.0, 0.0), TUBE).to_f64();
        assert!(n[0] > 0.0 && n[1] == 0.0 && n[2] == 0.0, "{n:?}");
        let n = normal(Vector3::new(0.75, 0.0, 0.0), TUBE).to_f64();
        assert!(n[0] < 0.0, "{n:?}");
        let n = normal(Vector3::new(0.0, -1.0, 0.25), TUBE).to_f64();
        assert!(n[2] > 0.0 && n[1].abs() < 1e-12, "{n:?}");
    }
}
