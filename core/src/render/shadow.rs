//! Shadow rays (`inshadow`, digest §4.7 and §5): from the hit point toward the light, bounded
//! by the light's distance for a point light. The shaded object itself is skipped: a convex
//! closed primitive cannot shadow its own lit side, and skipping it makes shadow acne
//! impossible without any epsilon.
//!
//! Beyond the thesis (which tested every other object): an object is tested only when the
//! shadow ray's segment passes through its bounding sphere (`optimize::shadow`), and the object
//! that blocked the previous shadow ray is tried first (a shadow cache). Both only skip tests
//! whose answer is known or reorder tests of a yes/no question, so the image is unchanged.
//! They are on with Extents (they are its three-dimensional counterpart) unless the
//! acceleration was built with the thesis's tuning.

use super::Statistics;
use crate::geometry::{Ray, Vector3};
use crate::number::Number;
use crate::scene::Scene;
use crate::shapes::Interval;

/// The object that blocked the last shadow ray, tried first by the next one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ShadowCache {
    pub last_blocker: Option<u16>,
    /// The object the last primary ray hit (see `nearest_hit_cached`).
    pub last_hit: Option<u16>,
}

pub fn in_shadow<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
) -> bool {
    in_shadow_cached(scene, shaded_object, point, to_light, light_distance, statistics, &mut ShadowCache::default())
}

pub fn in_shadow_cached<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
    cache: &mut ShadowCache,
) -> bool {
    in_shadow_culled(scene, shaded_object, point, to_light, light_distance, statistics, cache, &ShadowCulling::default())
}

/// Per-render shadow culling data, indexed by object (empty slices: none).
#[derive(Clone, Copy, Debug)]
pub struct ShadowCulling<'a, N> {
    /// For a point light: each object's cone of directions from the light.
    pub light_cones: &'a [(Vector3<N>, N)],
    /// For each receiving object, the objects among the first 128 that may shadow it (bit i:
    /// object i); objects from 128 on are always candidates.
    pub blockers: &'a [u128],
}

impl<N> Default for ShadowCulling<'_, N> {
    fn default() -> Self {
        Self { light_cones: &[], blockers: &[] }
    }
}

/// [`in_shadow_cached`] with, for a point light, each object's cone of directions from the light
/// (`ShadowBound::light_cone`, indexed by object; empty: none), checked before its capsule.
#[allow(clippy::too_many_arguments)]
pub fn in_shadow_culled<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
    cache: &mut ShadowCache,
    culling: &ShadowCulling<'_, N>,
) -> bool {
    statistics.shadow_rays += 1;
    let light_cones = culling.light_cones;
    let from_light = -to_light;
    let ray = Ray { origin: point, direction: to_light };
    let interval = Interval::below(light_distance);
    let acceleration = &scene.acceleration;
    let cull = acceleration.culls_shadows();
    let blocks = |index: usize, statistics: &mut Statistics| -> bool {
        if index == shaded_object {
            return false;
        }
        if cull && light_cones.get(index).is_some_and(|(axis, cosine)| from_light.dot(*axis) < *cosine) {
            return false;
        }
        if cull && !acceleration.may_shadow(index, point, to_light, light_distance) {
            return false;
        }
        let Some(object) = scene.objects.get(index) else { return false };
        statistics.shadow_tests += 1;
        object.primitive.occluded(&object.object_from_world.ray(&ray), interval)
    };
    let bits = if cull { culling.blockers.get(shaded_object).copied() } else { None };
    let listed = |index: usize| bits.is_none_or(|bits| index >= 128 || bits & (1u128 << index) != 0);
    let first = if cull { cache.last_blocker.map(usize::from).filter(|index| listed(*index)) } else { None };
    if let Some(index) = first {
        if blocks(index, statistics) {
            return true;
        }
    }
    let mut remaining = bits.unwrap_or(0);
    while remaining != 0 {
        let index = remaining.trailing_zeros() as usize;
        remaining &= remaining - 1;
        if Some(index) == first {
            continue;
        }
        if blocks(index, statistics) {
            cache.last_blocker = Some(index as u16);
            return true;
        }
    }
    let start = if bits.is_some() { 128 } else { 0 };
    for index in start..scene.objects.len() {
        if Some(index) == first {
            continue;
        }
        if blocks(index, statistics) {
            cache.last_blocker = Some(index as u16);
            return true;
        }
    }
    false
}
