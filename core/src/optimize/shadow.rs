//! Shadow-ray culling, beyond the thesis (which tested every other object, digest §4.7): each
//! object keeps a bounding sphere of its volume, and a shadow ray tests an object only when the
//! ray's segment passes through that sphere. The check is a dot product, a vector length and
//! two comparisons in the number type, against a ray–object test's transform and quadric.
//! It is conservative: the sphere's radius is widened before conversion, and the distance is
//! computed with `length3` (which never overflows in narrow fixed-point types).

use crate::geometry::Vector3;
use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadowBound<N> {
    pub centre: Vector3<N>,
    /// Widened radius; `N::MAX` means "always test".
    pub radius: N,
}

impl<N: Number> ShadowBound<N> {
    pub fn always() -> Self {
        Self { centre: Vector3::zero(), radius: N::MAX }
    }

    pub fn new(centre: [f64; 3], radius: f64) -> Self {
        let scale = libm::sqrt(centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2]) + radius + 1.0;
        let widened = radius * (1.0 + 1e-3) + 1e-3 * scale;
        if !widened.is_finite() || !N::can_represent(widened) || !centre.iter().all(|c| N::can_represent(*c)) {
            return Self::always();
        }
        Self { centre: Vector3::from_f64(centre), radius: N::from_f64(widened) }
    }

    /// Whether the segment from `point` along unit `direction` up to `length` may meet the
    /// sphere.
    #[inline]
    pub fn may_block(&self, point: Vector3<N>, direction: Vector3<N>, length: N) -> bool {
        if self.radius == N::MAX {
            return true;
        }
        let offset = self.centre - point;
        let along = offset.dot(direction);
        if along < -self.radius || along - self.radius > length {
            return false;
        }
        (offset - direction * along).length() <= self.radius
    }
}
