//! Shadow rays (`inshadow`, digest §4.7 and §5): from the hit point toward the light, bounded
//! by the light's distance for a point light. The shaded object itself is skipped: a convex
//! closed primitive cannot shadow its own lit side, and skipping it makes shadow acne
//! impossible without any epsilon.

use super::Statistics;
use crate::geometry::{Ray, Vector3};
use crate::number::Number;
use crate::scene::Scene;
use crate::shapes::Interval;

pub fn in_shadow<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
) -> bool {
    statistics.shadow_rays += 1;
    let ray = Ray { origin: point, direction: to_light };
    let interval = Interval::below(light_distance);
    for (index, object) in scene.objects.iter().enumerate() {
        if index == shaded_object {
            continue;
        }
        statistics.shadow_tests += 1;
        if object.primitive.occluded(&object.object_from_world.ray(&ray), interval) {
            return true;
        }
    }
    false
}
