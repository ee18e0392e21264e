//! The nearest hit of a secondary ray (reflected or refracted, thesis §5.2.1): a ray that
//! starts anywhere, so the screen-space optimizations do not apply. Every object is a
//! candidate; its bounding sphere (`optimize::bounding_sphere`) is checked before its
//! primitive. The ray's own object is tested too: a refracted ray inside a sphere must find the
//! sphere's far side. Exact ties go to the object that comes first, as for primary rays.

use super::primary::NearestHit;
use super::Statistics;
use crate::geometry::Ray;
use crate::number::Number;
use crate::scene::Scene;
use crate::shapes::Interval;

pub(crate) fn nearest_secondary_hit<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    ray: &Ray<N>,
    statistics: &mut Statistics,
) -> Option<NearestHit<N>> {
    let mut nearest: Option<NearestHit<N>> = None;
    for (index, object) in scene.objects.iter().enumerate() {
        let reach = nearest.map_or(N::MAX, |best| best.t);
        if !scene.bounding_sphere(index).may_meet(ray.origin, ray.direction, reach) {
            continue;
        }
        // Objects come in order, so an equal t never replaces an earlier object.
        let interval = nearest.map_or(Interval::unbounded(), |best| Interval::below(best.t));
        statistics.secondary_tests += 1;
        if let Some(hit) = object.primitive.intersect(&object.object_from_world.ray(ray), interval) {
            nearest = Some(NearestHit { object: index, t: hit.t, local_normal: hit.normal });
        }
    }
    nearest
}
