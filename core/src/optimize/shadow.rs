//! Shadow-ray culling, beyond the thesis (which tested every other object, digest §4.7): each
//! object keeps a bounding capsule (a segment and a radius: a point for spheres and cubes, the
//! axis for cylinders and cones), and a shadow ray tests an object only when the ray's segment
//! passes within the radius of that segment. The check is a few dot products and one vector
//! length in the number type, against a ray–object test's transform and quadric.
//! It is conservative: the radius is widened before conversion, the closest points of the two
//! segments are found exactly (Ericson, *Real-Time Collision Detection* §5.1.9), nearly
//! parallel segments are always tested, and lengths use `length3` (which never overflows in
//! narrow fixed-point types).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::geometry::Vector3;
use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowBound<N> {
    /// The middle of the capsule's segment.
    pub centre: Vector3<N>,
    /// Unit direction of the segment (zero for a point).
    pub axis: Vector3<N>,
    /// Half the length of the segment.
    pub half: N,
    /// Widened radius; `N::MAX` means "always test".
    pub radius: N,
    /// `radius + half`: the radius of a sphere about `centre` holding the capsule.
    pub reach: N,
}

impl<N: Number> ShadowBound<N> {
    /// Every byte zero: the value before the acceleration is built.
    pub const UNSET: Self = Self {
        centre: Vector3 { x: N::ZERO, y: N::ZERO, z: N::ZERO },
        axis: Vector3 { x: N::ZERO, y: N::ZERO, z: N::ZERO },
        half: N::ZERO,
        radius: N::ZERO,
        reach: N::ZERO,
    };

    pub fn always() -> Self {
        Self { centre: Vector3::zero(), axis: Vector3::zero(), half: N::ZERO, radius: N::MAX, reach: N::MAX }
    }

    /// The capsule from `start` to `end` with `radius`, widened for rounding.
    pub fn new(start: [f64; 3], end: [f64; 3], radius: f64) -> Self {
        let d = [end[0] - start[0], end[1] - start[1], end[2] - start[2]];
        let length = libm::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        let axis = if length > 0.0 { d.map(|c| c / length) } else { [0.0; 3] };
        let centre = [0, 1, 2].map(|k| (start[k] + end[k]) / 2.0);
        let scale = libm::sqrt(centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2]) + length + radius + 1.0;
        let widened = radius * (1.0 + 1e-3) + 1e-3 * scale;
        let half = length / 2.0 * (1.0 + 1e-9);
        let representable = centre.iter().all(|c| N::can_represent(*c)) && N::can_represent(widened + half);
        if !widened.is_finite() || !representable {
            return Self::always();
        }
        Self {
            centre: Vector3::from_f64(centre),
            axis: Vector3::from_f64(axis),
            half: N::from_f64(half),
            radius: N::from_f64(widened),
            reach: N::from_f64(widened + half),
        }
    }

    /// Whether the segment from `point` along unit `direction` up to `length` may come within
    /// the radius of the capsule's segment.
    #[inline]
    pub fn may_block(&self, point: Vector3<N>, direction: Vector3<N>, length: N) -> bool {
        if self.radius == N::MAX {
            return true;
        }
        // First the sphere about the centre that holds the capsule: behind the point, beyond
        // the light, or off the ray's line in some coordinate.
        let w = self.centre - point;
        let b = direction.dot(w);
        if b < -self.reach || b - self.reach > length {
            return false;
        }
        let off = w - direction * b;
        if off.x.abs() > self.reach || off.y.abs() > self.reach || off.z.abs() > self.reach {
            return false;
        }
        // Then the capsule: the closest points of the two segments (s on the ray in
        // [0, length], t on the axis in [−half, half]).
        let clamp = |value: N, low: N, high: N| if value < low { low } else if value > high { high } else { value };
        let (s, t) = if self.half == N::ZERO {
            (clamp(b, N::ZERO, length), N::ZERO)
        } else {
            let a = direction.dot(self.axis);
            let c = self.axis.dot(w);
            let denominator = N::ONE - a * a;
            if denominator < N::from_f64(1e-4) {
                return true;
            }
            let Some(s) = (b - a * c).checked_div(denominator) else { return true };
            let t = clamp(clamp(s, N::ZERO, length) * a - c, -self.half, self.half);
            let s = clamp(b + t * a, N::ZERO, length);
            (s, clamp(s * a - c, -self.half, self.half))
        };
        let gap = direction * s - self.axis * t - w;
        if gap.x.abs() > self.radius || gap.y.abs() > self.radius || gap.z.abs() > self.radius {
            return false;
        }
        gap.length() <= self.radius
    }
}

impl<N: Number> ShadowBound<N> {
    /// For a point light at `light`: the cone of directions from the light that meet the
    /// capsule's enclosing sphere, as (unit axis, cosine of the widened half-angle). A shadow
    /// ray from P can meet the capsule only if the direction from the light to P lies in the
    /// cone. `(zero, −1)` (always inside) when the light is within the sphere.
    pub fn light_cone(&self, light: Vector3<N>) -> (Vector3<N>, N) {
        let always = (Vector3::zero(), -N::ONE);
        if self.radius == N::MAX {
            return always;
        }
        let v = [0, 1, 2].map(|k| self.centre.to_f64()[k] - light.to_f64()[k]);
        let distance = libm::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        let reach = self.reach.to_f64();
        if !(distance > reach * (1.0 + 1e-6)) {
            return always;
        }
        let half_angle = libm::asin(reach / distance) + 1e-3;
        if half_angle >= core::f64::consts::FRAC_PI_2 {
            return always;
        }
        (Vector3::from_f64(v.map(|c| c / distance)), N::from_f64(libm::cos(half_angle) - 1e-6))
    }
}

/// Whether some shadow ray from a point of `receiver` toward the light may meet `blocker`
/// (their capsules' enclosing spheres, in `f64`, widened): toward a point light, when the two
/// spheres' cones of directions from the light overlap and the blocker's near side is nearer
/// the light than the receiver's far side; toward a directional light, when the blocker's
/// sphere comes within reach of the receiver's sphere swept toward the light.
pub fn may_block_object<N: Number>(receiver: &ShadowBound<N>, blocker: &ShadowBound<N>, light: Option<[f64; 3]>, direction: Option<[f64; 3]>) -> bool {
    if receiver.radius == N::MAX || blocker.radius == N::MAX {
        return true;
    }
    let (r, b) = (receiver.centre.to_f64(), blocker.centre.to_f64());
    let (r_reach, b_reach) = (receiver.reach.to_f64(), blocker.reach.to_f64());
    let margin = 1e-3 * (1.0 + r_reach + b_reach);
    let dot = |a: [f64; 3], c: [f64; 3]| a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
    if let Some(light) = light {
        let a = [r[0] - light[0], r[1] - light[1], r[2] - light[2]];
        let c = [b[0] - light[0], b[1] - light[1], b[2] - light[2]];
        let (la, lc) = (libm::sqrt(dot(a, a)), libm::sqrt(dot(c, c)));
        if la <= r_reach + margin || lc <= b_reach + margin {
            return true;
        }
        if lc - b_reach > la + r_reach + margin {
            return false;
        }
        let angle = libm::acos((dot(a, c) / (la * lc)).clamp(-1.0, 1.0));
        return angle <= libm::asin(r_reach / la) + libm::asin(b_reach / lc) + 1e-3;
    }
    if let Some(d) = direction {
        let length = libm::sqrt(dot(d, d));
        let d = d.map(|x| x / length);
        let w = [b[0] - r[0], b[1] - r[1], b[2] - r[2]];
        let along = dot(w, d);
        let reach = r_reach + b_reach + margin;
        if along < -reach {
            return false;
        }
        let off = [w[0] - d[0] * along, w[1] - d[1] * along, w[2] - d[2] * along];
        return libm::sqrt(dot(off, off)) <= reach;
    }
    true
}
