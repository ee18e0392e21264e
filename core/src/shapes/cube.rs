//! The unit cube `[0,1]^3` (`tracecube`), by slabs: the ray is inside the cube where it is
//! between all three pairs of planes. Bounds are inclusive, as in the thesis.

use super::hit::Hit;
use super::ScaledInterval;
use crate::geometry::{Ray, Vector3};
use crate::number::Number;

/// A ray parameter where the ray crosses the surface, and the outward normal there.
type Crossing<N> = (N, Vector3<N>);

/// Entry and exit parameters and the outward normals there, or `None` for a miss.
#[inline]
fn span<N: Number>(ray: &Ray<N>) -> Option<(Crossing<N>, Crossing<N>)> {
    let (p, d) = (ray.origin.to_array(), ray.direction.to_array());
    let mut enter = (-N::MAX, Vector3::zero());
    let mut exit = (N::MAX, Vector3::zero());
    let mut moving = false;
    for axis in 0..3 {
        if d[axis] == N::ZERO {
            // Parallel to this pair of planes: inside the slab or a miss, no division.
            if p[axis] < N::ZERO || p[axis] > N::ONE {
                return None;
            }
            continue;
        }
        moving = true;
        let low = (N::ZERO - p[axis]).checked_div(d[axis])?;
        let high = (N::ONE - p[axis]).checked_div(d[axis])?;
        let mut outward = [N::ZERO; 3];
        // Entering through the low plane when moving up, through the high plane when moving down.
        let (near, far, near_sign) = if d[axis] > N::ZERO { (low, high, -N::ONE) } else { (high, low, N::ONE) };
        outward[axis] = near_sign;
        if near > enter.0 {
            enter = (near, Vector3::new(outward[0], outward[1], outward[2]));
        }
        outward[axis] = -near_sign;
        if far < exit.0 {
            exit = (far, Vector3::new(outward[0], outward[1], outward[2]));
        }
    }
    (moving && enter.0 <= exit.0).then_some((enter, exit))
}

pub fn intersect<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> Option<Hit<N>> {
    let (enter, exit) = span(ray)?;
    [enter, exit].into_iter().find(|(t, _)| interval.contains(*t)).map(|(t, normal)| Hit { t, normal })
}

pub fn occluded<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> bool {
    match span(ray) {
        Some((enter, exit)) => interval.contains(enter.0) || interval.contains(exit.0),
        None => false,
    }
}

/// Entry and exit, at any `t`, with the outward normals (for CSG's spans).
pub fn crossings<N: Number>(ray: &Ray<N>) -> [Option<Crossing<N>>; 2] {
    match span(ray) {
        Some((enter, exit)) => [Some(enter), Some(exit)],
        None => [None, None],
    }
}
