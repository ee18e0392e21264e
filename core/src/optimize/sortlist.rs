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
//!   |eye − centre| minus its largest semi-axis).
//!
//! Bounds are computed in `f64` and lowered by a margin before conversion, so rounding in the
//! number type cannot make an object's computed `t` fall below its bound. The loop breaks only
//! when the bound is strictly greater than the nearest `t`: an equal `t` may still win the tie
//! for a lower object number.

use super::bounding_volume::{dot, ObjectGeometry};
use super::projection::{Screen, View};

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
        View::Perspective { eye } => geometry.distance_lower_bound(eye),
    };
    bound.is_finite().then(|| bound - 1e-3 * (bound.abs() + 1.0))
}

/// Sorts `order` (object numbers) by `bound`, ties by object number (insertion sort: stable,
/// no allocation, n² only at preprocess).
pub fn sort_by_bound<T: PartialOrd + Copy>(order: &mut [u16], bound: impl Fn(usize) -> T) {
    for i in 1..order.len() {
        let mut j = i;
        while j > 0 && bound(usize::from(order[j])) < bound(usize::from(order[j - 1])) {
            order.swap(j, j - 1);
            j -= 1;
        }
    }
}
