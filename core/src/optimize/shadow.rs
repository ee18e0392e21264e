//! Shadow-ray culling, beyond the thesis (which tested every other object, digest §4.7): each
//! object keeps a bounding capsule (a segment and a radius: a point for spheres and cubes, the
//! axis for cylinders and cones), and a shadow ray tests an object only when the ray's segment
//! passes within the radius of that segment. The check is a few dot products and one vector
//! length in the number type, against a ray–object test's transform and quadric.
//! It is conservative: the radius is widened before conversion, the closest points of the two
//! segments are found exactly (Ericson, *Real-Time Collision Detection* §5.1.9), nearly
//! parallel segments are always tested, and lengths use `length3` (which never overflows in
//! narrow fixed-point types).

use crate::geometry::Vector3;
use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowBound<N> {
    /// One end of the capsule's segment.
    pub start: Vector3<N>,
    /// Unit direction of the segment (zero for a point).
    pub axis: Vector3<N>,
    /// Length of the segment.
    pub length: N,
    /// Widened radius; `N::MAX` means "always test".
    pub radius: N,
}

impl<N: Number> ShadowBound<N> {
    pub fn always() -> Self {
        Self { start: Vector3::zero(), axis: Vector3::zero(), length: N::ZERO, radius: N::MAX }
    }

    /// The capsule from `start` to `end` with `radius`, widened for rounding.
    pub fn new(start: [f64; 3], end: [f64; 3], radius: f64) -> Self {
        let d = [end[0] - start[0], end[1] - start[1], end[2] - start[2]];
        let length = libm::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        let axis = if length > 0.0 { d.map(|c| c / length) } else { [0.0; 3] };
        let scale = libm::sqrt(start[0] * start[0] + start[1] * start[1] + start[2] * start[2]) + length + radius + 1.0;
        let widened = radius * (1.0 + 1e-3) + 1e-3 * scale;
        let representable = start.iter().chain(end.iter()).all(|c| N::can_represent(*c)) && N::can_represent(widened + length);
        if !widened.is_finite() || !representable {
            return Self::always();
        }
        Self { start: Vector3::from_f64(start), axis: Vector3::from_f64(axis), length: N::from_f64(length), radius: N::from_f64(widened) }
    }

    /// Whether the segment from `point` along unit `direction` up to `reach` may come within
    /// the radius of the capsule's segment.
    #[inline]
    pub fn may_block(&self, point: Vector3<N>, direction: Vector3<N>, reach: N) -> bool {
        if self.radius == N::MAX {
            return true;
        }
        let w = self.start - point;
        let b = direction.dot(w);
        // The capsule lies wholly behind the point or beyond the light along the ray.
        if b + self.length < -self.radius || b - self.length - self.radius > reach {
            return false;
        }
        let a = direction.dot(self.axis);
        let c = self.axis.dot(w);
        let clamp = |value: N, high: N| if value < N::ZERO { N::ZERO } else if value > high { high } else { value };
        let t = if self.length == N::ZERO {
            N::ZERO
        } else {
            let denominator = N::ONE - a * a;
            if denominator < N::from_f64(1e-4) {
                return true;
            }
            match (b - a * c).checked_div(denominator) {
                Some(s) => clamp(clamp(s, reach) * a - c, self.length),
                None => return true,
            }
        };
        let s = clamp(b + t * a, reach);
        let t = if self.length == N::ZERO { N::ZERO } else { clamp(s * a - c, self.length) };
        let gap = direction * s - self.axis * t - w;
        // Cheap rejection per component before the length.
        if gap.x.abs() > self.radius || gap.y.abs() > self.radius || gap.z.abs() > self.radius {
            return false;
        }
        gap.length() <= self.radius
    }
}
