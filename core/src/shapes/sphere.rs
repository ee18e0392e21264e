//! The unit sphere at the origin (`tracesphere`, `stracesphere`).

use super::hit::Hit;
use super::{quadratic, ScaledInterval};
use crate::geometry::{Ray, Vector3};
use crate::number::Number;

// Inline into `intersect` and `occluded`: its two optional roots returned through memory cost
// more than the test (51 k instructions of a Cortex-M4F snooker frame).
#[inline]
fn candidate_roots<N: Number>(ray: &Ray<N>) -> Option<[Option<N>; 2]> {
    let p = ray.origin.to_array();
    let d = ray.direction.to_array();
    let a = N::dot3(d, d);
    let b = N::dot3(p, d);
    let discriminant = quadratic::unit_discriminant(p, d, a, b)?;
    if discriminant < N::ZERO {
        return None;
    }
    let c = N::dot3(p, p) - N::ONE;
    Some(quadratic::roots(a, b, c, discriminant))
}

pub fn intersect<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> Option<Hit<N>> {
    let roots = candidate_roots(ray)?;
    let t = roots.iter().flatten().copied().find(|t| interval.contains(*t))?;
    Some(Hit { t, normal: ray.at(t) })
}

pub fn occluded<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> bool {
    match candidate_roots(ray) {
        Some(roots) => roots.iter().flatten().any(|t| interval.contains(*t)),
        None => false,
    }
}


/// Both crossings, at any `t`, with the outward normal (for CSG's spans).
pub fn crossings<N: Number>(ray: &Ray<N>) -> [Option<(N, Vector3<N>)>; 2] {
    match candidate_roots(ray) {
        Some(roots) => roots.map(|root| root.map(|t| (t, ray.at(t)))),
        None => [None, None],
    }
}
