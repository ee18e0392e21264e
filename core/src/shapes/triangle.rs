//! The unit triangle (0,0,0), (1,0,0), (0,1,0) in the plane z = 0: its transform maps it onto
//! any triangle of a scene (NFF's polygons, split at preparation, and patches). In its own
//! space the test is a plane and two barycentric coordinates, u ≥ 0, v ≥ 0, u + v ≤ 1.

use super::{Hit, ScaledInterval};
use crate::geometry::{Ray, Vector3};
use crate::number::Number;

/// Where the ray crosses the triangle's plane inside it, with the plane's normal +z; a ray in
/// the plane (d.z = 0) never meets it.
#[inline]
fn surface<N: Number>(ray: &Ray<N>) -> Option<(N, Vector3<N>)> {
    let (p, d) = (ray.origin, ray.direction);
    if d.z == N::ZERO {
        return None;
    }
    let t = (-p.z).checked_div(d.z)?;
    let (u, v) = (p.x + d.x * t, p.y + d.y * t);
    (u >= N::ZERO && v >= N::ZERO && u + v <= N::ONE).then(|| (t, Vector3::new(N::ZERO, N::ZERO, N::ONE)))
}

pub fn intersect<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> Option<Hit<N>> {
    surface(ray).filter(|(t, _)| interval.contains(*t)).map(|(t, normal)| Hit { t, normal })
}

pub fn occluded<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> bool {
    surface(ray).is_some_and(|(t, _)| interval.contains(t))
}

/// The crossing, at any `t` (an open surface: no solid may use it, see `Primitive::is_closed`).
pub fn crossings<N: Number>(ray: &Ray<N>) -> [Option<(N, Vector3<N>)>; 1] {
    [surface(ray)]
}
