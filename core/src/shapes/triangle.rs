//! The unit triangle (0,0,0), (1,0,0), (0,1,0) in the plane z = 0: its transform maps it onto
//! any triangle of a scene (NFF's polygons, split at preparation, and patches). In its own
//! space the test is a plane and two barycentric coordinates, u ≥ 0, v ≥ 0, u + v ≤ 1.

use super::{Hit, ScaledInterval};
use crate::geometry::{Ray, Vector3};
use crate::model::VertexNormals;
use crate::number::Number;

/// Where the ray crosses the triangle's plane inside it, `t` and the barycentric (u, v) there
/// (the hit point's x and y); a ray in the plane (d.z = 0) never meets it.
#[inline]
fn crossing<N: Number>(ray: &Ray<N>) -> Option<(N, N, N)> {
    let (p, d) = (ray.origin, ray.direction);
    if d.z == N::ZERO {
        return None;
    }
    let t = (-p.z).checked_div(d.z)?;
    let (u, v) = (p.x + d.x * t, p.y + d.y * t);
    (u >= N::ZERO && v >= N::ZERO && u + v <= N::ONE).then_some((t, u, v))
}

/// The crossing with the plane's normal, +z.
#[inline]
fn surface<N: Number>(ray: &Ray<N>) -> Option<(N, Vector3<N>)> {
    crossing(ray).map(|(t, _, _)| (t, Vector3::new(N::ZERO, N::ZERO, N::ONE)))
}

/// A patch: the triangle's hit with the corners' normals interpolated there (NFF's `pp`).
pub fn intersect_patch<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>, normals: VertexNormals) -> Option<Hit<N>> {
    crossing(ray).filter(|(t, _, _)| interval.contains(*t)).map(|(t, u, v)| Hit { t, normal: normals.at(u, v) })
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
