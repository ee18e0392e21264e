//! The unit cylinder: radius 1 about +z, from z = 0 to z = 1, both caps (`tracecylinder`).

use super::hit::{self, Hit};
use super::{quadratic, ScaledInterval};
use crate::geometry::{Ray, Vector3};
use crate::number::Number;

/// Every surface the ray meets, as (t, normal), in no particular order; `None` entries are
/// misses.
#[inline]
fn surfaces<N: Number>(ray: &Ray<N>) -> [Option<(N, Vector3<N>)>; 4] {
    let (p, d) = (ray.origin, ray.direction);
    let mut found = [None; 4];
    // Caps: the planes z = 0 and z = 1, inside the unit disc.
    if d.z != N::ZERO {
        for (slot, (plane, normal_z)) in [(N::ZERO, -N::ONE), (N::ONE, N::ONE)].into_iter().enumerate() {
            if let Some(t) = (plane - p.z).checked_div(d.z) {
                let (x, y) = (p.x + d.x * t, p.y + d.y * t);
                if x * x + y * y <= N::ONE {
                    found[slot] = Some((t, Vector3::new(N::ZERO, N::ZERO, normal_z)));
                }
            }
        }
    }
    // Side: x² + y² = 1 for 0 ≤ z ≤ 1. A ray parallel to the axis (A = 0) never meets it.
    let a = d.x * d.x + d.y * d.y;
    if a > N::ZERO {
        let b = p.x * d.x + p.y * d.y;
        let flat_p = [p.x, p.y, N::ZERO];
        let flat_d = [d.x, d.y, N::ZERO];
        if let Some(discriminant) = quadratic::unit_discriminant(flat_p, flat_d, a, b) {
            if discriminant >= N::ZERO {
                let c = p.x * p.x + p.y * p.y - N::ONE;
                for (slot, root) in quadratic::roots(a, b, c, discriminant).into_iter().enumerate() {
                    if let Some(t) = root {
                        let hit = ray.at(t);
                        if hit.z >= N::ZERO && hit.z <= N::ONE {
                            found[2 + slot] = Some((t, Vector3::new(hit.x, hit.y, N::ZERO)));
                        }
                    }
                }
            }
        }
    }
    found
}

pub fn intersect<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> Option<Hit<N>> {
    hit::nearest(surfaces(ray), interval)
}

pub fn occluded<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> bool {
    hit::any(surfaces(ray), interval)
}

/// Every crossing, at any `t`, with the outward normal (for CSG's spans).
pub fn crossings<N: Number>(ray: &Ray<N>) -> [Option<(N, Vector3<N>)>; 4] {
    surfaces(ray)
}
