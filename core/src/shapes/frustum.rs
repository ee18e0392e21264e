//! The open frustum (NFF's `c`, Haines' SPD): radius `r` at z = 0 to 1 at z = 1, no caps, so a
//! ray may meet its inside. On it x² + y² = ρ(z)² with ρ(z) = r + s·z, s = 1 − r: an open
//! cylinder when r = 1, an open cone with its apex at the origin when r = 0.

use super::hit::{self, Hit};
use super::{quadratic, ScaledInterval};
use crate::geometry::{Ray, Vector3};
use crate::number::Number;

/// The outward normal at a point of the side: the gradient of x² + y² − ρ(z)², halved,
/// (x, y, −s·ρ(z)); at a cone's apex, where it vanishes, the axis.
fn side_normal<N: Number>(hit: Vector3<N>, r: N, s: N) -> Vector3<N> {
    let rho = r + s * hit.z;
    if hit.x == N::ZERO && hit.y == N::ZERO && rho == N::ZERO {
        Vector3::new(N::ZERO, N::ZERO, -N::ONE)
    } else {
        Vector3::new(hit.x, hit.y, -(s * rho))
    }
}

#[inline]
fn surfaces<N: Number>(ray: &Ray<N>, r: N) -> [Option<(N, Vector3<N>)>; 2] {
    let (p, d) = (ray.origin, ray.direction);
    let s = N::ONE - r;
    let mut found = [None; 2];
    // (p + t d) on the side: A t² + 2 b t + c = 0 with the radius along the ray k0 + kd t.
    let (k0, kd) = (r + s * p.z, s * d.z);
    let a = N::dot3([d.x, d.y, kd], [d.x, d.y, -kd]);
    let b = N::dot3([p.x, p.y, k0], [d.x, d.y, -kd]);
    let c = N::dot3([p.x, p.y, k0], [p.x, p.y, -k0]);
    let mut side = |slot: usize, t: N| {
        let hit = ray.at(t);
        if hit.z >= N::ZERO && hit.z <= N::ONE {
            if let Some(place) = found.get_mut(slot) {
                *place = Some((t, side_normal(hit, r, s)));
            }
        }
    };
    if a == N::ZERO {
        // Parallel to a generator line (or, for the cylinder, to the axis: b = 0 then).
        if let Some(t) = (-c).checked_div(b + b) {
            side(0, t);
        }
    } else {
        let discriminant = N::dot3([b, -a, N::ZERO], [b, c, N::ZERO]);
        if discriminant >= N::ZERO {
            let [first, second] = quadratic::roots(a, b, c, discriminant);
            if let Some(t) = first {
                side(0, t);
            }
            if let Some(t) = second {
                side(1, t);
            }
        }
    }
    found
}

pub fn intersect<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>, r: N) -> Option<Hit<N>> {
    hit::nearest(surfaces(ray, r), interval)
}

pub fn occluded<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>, r: N) -> bool {
    hit::any(surfaces(ray, r), interval)
}

/// Every crossing, at any `t` (an open surface: no solid may use it, see `Primitive::is_closed`).
pub fn crossings<N: Number>(ray: &Ray<N>, r: N) -> [Option<(N, Vector3<N>)>; 2] {
    surfaces(ray, r)
}
