//! Bounding spheres for secondary rays (thesis §5.2.1: "bounding spheres" among the options
//! for rays that do not leave the eye). The four screen-space optimizations serve primary rays
//! only; a reflected or refracted ray starts anywhere, so each object gets a world-space sphere
//! that a ray must pass near before its primitive is tested.
//!
//! The test uses no squares (`fixed16`'s range is ±32768): the ray misses when the sphere lies
//! wholly behind its origin or beyond its end, or when the offset from the closest point on
//! the ray to the centre exceeds the radius in some coordinate. The radius carries a margin
//! for the type's rounding, and a term growing with the distance along the ray for the error
//! of its unit direction; types whose directions are farther off (`Number::SHADOW_CULLING_HOLDS`
//! false) test every object.

use crate::geometry::{Matrix4, Vector3};
use crate::number::Number;
use crate::model::Primitive;

/// A world-space sphere holding an object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingSphere<N> {
    pub centre: Vector3<N>,
    pub radius: N,
}

/// The relative margin on the radius and the direction error allowed per unit of distance.
const MARGIN_EXPONENT: i32 = -10;

impl<N: Number> BoundingSphere<N> {
    /// A sphere that can never be excluded.
    pub const EVERYWHERE: Self = Self { centre: Vector3 { x: N::ZERO, y: N::ZERO, z: N::ZERO }, radius: N::MAX };

    /// The sphere about the centre of the primitive's box in world space through its eight
    /// corners, widened by the margin (computed in `f64` at preparation).
    pub fn of(primitive: Primitive, world_from_object: &Matrix4) -> Self {
        let [low, high] = primitive.local_box();
        let corners: [[f64; 3]; 8] = core::array::from_fn(|i| {
            let pick = |axis: usize| if i >> axis & 1 == 0 { low[axis] } else { high[axis] };
            world_from_object.transform_point([pick(0), pick(1), pick(2)])
        });
        let centre: [f64; 3] = core::array::from_fn(|axis| corners.iter().map(|c| c[axis]).sum::<f64>() / 8.0);
        let radius = corners
            .iter()
            .map(|c| libm::sqrt((0..3).map(|axis| (c[axis] - centre[axis]) * (c[axis] - centre[axis])).sum::<f64>()))
            .fold(0.0, f64::max);
        let largest = centre.iter().fold(radius, |m, c| m.max(c.abs()));
        let widened = radius + libm::ldexp(largest + 1.0, MARGIN_EXPONENT);
        if !N::can_represent(widened) || !centre.iter().all(|c| N::can_represent(*c)) {
            return Self::EVERYWHERE;
        }
        Self { centre: Vector3::from_f64(centre), radius: N::from_f64(widened) + N::RESOLUTION.times_power_of_two(4) }
    }

    /// Whether the ray from `origin` along the unit `direction`, up to `length`, may meet the
    /// sphere (false only when it certainly does not).
    #[inline]
    pub fn may_meet(&self, origin: Vector3<N>, direction: Vector3<N>, length: N) -> bool {
        if self.radius == N::MAX || !N::SHADOW_CULLING_HOLDS {
            return true;
        }
        let w = self.centre - origin;
        let b = direction.dot(w);
        if b < -self.radius || b - self.radius > length {
            return false;
        }
        let off = w - direction * b;
        let reach = self.radius + b.abs().times_power_of_two(MARGIN_EXPONENT);
        !(off.x.abs() > reach || off.y.abs() > reach || off.z.abs() > reach)
    }
}
