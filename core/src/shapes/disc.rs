//! The unit disc: radius 1 about the origin in the plane z = 0, seen from both sides. An open
//! surface (it encloses nothing, so no solid may take it as an operand: `Primitive::is_closed`).
//! A closed cylinder of height 0 is not one: its caps coincide and its side is degenerate. In its
//! own space the test is the plane and `x² + y² ≤ 1` where the ray crosses it.

use super::{Hit, ScaledInterval};
use crate::geometry::{Ray, Vector3};
use crate::number::Number;

/// Where the ray crosses the plane inside the disc, and the plane's normal, +z; a ray in the
/// plane (d.z = 0) never meets it.
#[inline]
fn surface<N: Number>(ray: &Ray<N>) -> Option<(N, Vector3<N>)> {
    let (p, d) = (ray.origin, ray.direction);
    if d.z == N::ZERO {
        return None;
    }
    let t = (-p.z).checked_div(d.z)?;
    let (x, y) = (p.x + d.x * t, p.y + d.y * t);
    (x * x + y * y <= N::ONE).then_some((t, Vector3::new(N::ZERO, N::ZERO, N::ONE)))
}

pub fn intersect<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> Option<Hit<N>> {
    surface(ray).filter(|(t, _)| interval.contains(*t)).map(|(t, normal)| Hit { t, normal })
}

pub fn occluded<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> bool {
    surface(ray).is_some_and(|(t, _)| interval.contains(t))
}

/// The crossing, at any `t` (an open surface: no solid uses it).
pub fn crossings<N: Number>(ray: &Ray<N>) -> [Option<(N, Vector3<N>)>; 1] {
    [surface(ray)]
}
