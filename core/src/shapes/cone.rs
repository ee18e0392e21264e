//! The unit cone: apex at the origin, axis +z, base of radius 1 at z = 1, capped
//! (`tracecone`). Side normal is the gradient of x² + y² − z², i.e. (x, y, −z); the thesis's
//! (x, y, √(1 − z²)) was wrong (digest §11 B3).

use super::hit::{self, Hit};
use super::{quadratic, ScaledInterval};
use crate::geometry::{Ray, Vector3};
use crate::number::Number;

fn side_normal<N: Number>(hit: Vector3<N>) -> Vector3<N> {
    // At the apex the gradient vanishes; the axis is the sensible outward direction there.
    if hit.x == N::ZERO && hit.y == N::ZERO && hit.z == N::ZERO {
        Vector3::new(N::ZERO, N::ZERO, -N::ONE)
    } else {
        Vector3::new(hit.x, hit.y, -hit.z)
    }
}

/// `b² − a c` of the side's quadratic without subtracting the two fourth-order terms: for
/// any symmetric Q, (pᵀQd)² − (pᵀQp)(dᵀQd) = −wᵀ adj(Q) w with w = p × d, and adj(Q) =
/// diag(−1, −1, 1) here, so Δ = wₓ² + w_y² − w_z². For a thin or distant cone b² and a c are
/// huge and nearly equal (a cone 10⁻⁴ thick lost 1 % of its pixels in f32); the cross
/// product cancels only second-order terms, each formed exactly by `dot3` in fixed point.
#[inline]
fn discriminant<N: Number>(p: Vector3<N>, d: Vector3<N>) -> N {
    let zero = N::ZERO;
    let w = [
        N::dot3([p.y, -p.z, zero], [d.z, d.y, zero]),
        N::dot3([p.z, -p.x, zero], [d.x, d.z, zero]),
        N::dot3([p.x, -p.y, zero], [d.y, d.x, zero]),
    ];
    N::dot3(w, [w[0], w[1], -w[2]])
}

#[inline]
fn surfaces<N: Number>(ray: &Ray<N>) -> [Option<(N, Vector3<N>)>; 3] {
    let (p, d) = (ray.origin, ray.direction);
    let mut found = [None; 3];
    // Base: z = 1 inside the unit disc.
    if d.z != N::ZERO {
        if let Some(t) = (N::ONE - p.z).checked_div(d.z) {
            let (x, y) = (p.x + d.x * t, p.y + d.y * t);
            if x * x + y * y <= N::ONE {
                found[0] = Some((t, Vector3::new(N::ZERO, N::ZERO, N::ONE)));
            }
        }
    }
    // Side: x² + y² − z² = 0 for 0 ≤ z ≤ 1, i.e. qᵀQq = 0 with Q = diag(1, 1, −1).
    let mirrored = |v: Vector3<N>| [v.x, v.y, -v.z];
    let a = N::dot3(d.to_array(), mirrored(d));
    let b = N::dot3(p.to_array(), mirrored(d));
    let c = N::dot3(p.to_array(), mirrored(p));
    let mut side = |slot: usize, t: N| {
        let hit = ray.at(t);
        if hit.z >= N::ZERO && hit.z <= N::ONE {
            found[slot] = Some((t, side_normal(hit)));
        }
    };
    if a == N::ZERO {
        // Parallel to a generator line: the quadratic degenerates to 2 b t + c = 0.
        if let Some(t) = (-c).checked_div(b + b) {
            side(1, t);
        }
    } else {
        let discriminant = discriminant(p, d);
        if discriminant >= N::ZERO {
            let [first, second] = quadratic::roots(a, b, c, discriminant);
            if let Some(t) = first {
                side(1, t);
            }
            if let Some(t) = second {
                side(2, t);
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
pub fn crossings<N: Number>(ray: &Ray<N>) -> [Option<(N, Vector3<N>)>; 3] {
    surfaces(ray)
}
