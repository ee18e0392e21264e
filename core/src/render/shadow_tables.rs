//! The light's culling tables, built once per render: for each light, each object's cone of
//! directions from it and which objects may shadow which (docs/optimizations.md).

use super::shadow_ray::ShadowCulling;
#[cfg(feature = "acceleration-tables")]
use crate::model::MAX_LIGHTS;
use crate::number::Number;
#[cfg(feature = "acceleration-tables")]
use crate::optimize::shadow_culling::{blocker_table, BlockerSet, DirectionChord, LightPosition, LightReach};
#[cfg(feature = "acceleration-tables")]
use crate::light::PreparedLight;
use crate::scene::{Objects, Scene};

/// Runs `body` with the per-render shadow tables, one per light: for a point light each
/// object's cone of directions from the light, and which objects may shadow which (on the
/// stack: for `f32` about 60 bytes per object and light while a table is built, 32 while `body`
/// runs). Both are built in the number type, in work linear in the objects and their
/// overlapping pairs (`optimize::shadow_culling::blocker_table`). Without the `acceleration-tables`
/// feature there are none.
#[cfg(feature = "acceleration-tables")]
pub(crate) fn with_shadow_culling<N: Number, R, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    let mut light_cones = [DirectionChord::ALWAYS; MAX_OBJECTS];
    let mut blockers = [BlockerSet::EMPTY; MAX_OBJECTS];
    let culls = scene.shadows && scene.acceleration.culls_shadows();
    let count = if culls { scene.objects.len().min(MAX_OBJECTS) } else { 0 };
    if culls {
        build_shadow_tables(scene, scene.light, count, &mut light_cones, &mut blockers);
    }
    let first = culling_of(scene.light, count, &light_cones, &blockers);
    if culls && !scene.more_lights.is_empty() {
        return with_more_lights_culling(scene, count, first, body);
    }
    body(&[first])
}

/// The tables of the lights after the first, out of line so that a scene with one light
/// keeps none of their stack.
#[cfg(feature = "acceleration-tables")]
#[inline(never)]
fn with_more_lights_culling<N: Number, R, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    count: usize,
    first: ShadowCulling<'_, N>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    const MORE: usize = MAX_LIGHTS - 1;
    let mut light_cones = [[DirectionChord::ALWAYS; MAX_OBJECTS]; MORE];
    let mut blockers = [[BlockerSet::EMPTY; MAX_OBJECTS]; MORE];
    for ((source, cones), sets) in scene.more_lights.iter().zip(light_cones.iter_mut()).zip(blockers.iter_mut()) {
        build_shadow_tables(scene, source.light, count, cones, sets);
    }
    let mut culling = [ShadowCulling::default(); MAX_LIGHTS];
    culling[0] = first;
    for (((slot, source), cones), sets) in culling.iter_mut().skip(1).zip(scene.more_lights.iter()).zip(light_cones.iter()).zip(blockers.iter()) {
        *slot = culling_of(source.light, count, cones, sets);
    }
    body(culling.get(..=scene.more_lights.len()).unwrap_or(&[]))
}

/// The culling of one light from its tables (only a point light has cones).
#[cfg(feature = "acceleration-tables")]
fn culling_of<'a, N: Number>(light: PreparedLight<N>, count: usize, light_cones: &'a [DirectionChord<N>], blockers: &'a [BlockerSet]) -> ShadowCulling<'a, N> {
    let cone_count = if matches!(light, PreparedLight::Point(_)) { count } else { 0 };
    ShadowCulling { light_cones: light_cones.get(..cone_count).unwrap_or(&[]), blockers: blockers.get(..count).unwrap_or(&[]) }
}

/// The footprints and the blocker table of one light, out of line: the footprints (40 bytes an
/// object in `f32`) are off the stack before the render's frames are on it.
#[cfg(feature = "acceleration-tables")]
#[inline(never)]
fn build_shadow_tables<N: Number, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    light: PreparedLight<N>,
    count: usize,
    light_cones: &mut [DirectionChord<N>; MAX_OBJECTS],
    blockers: &mut [BlockerSet; MAX_OBJECTS],
) {
    let light = match light {
        PreparedLight::Point(position) => LightPosition::Point(position),
        PreparedLight::Direction(direction) => LightPosition::Direction(direction),
    };
    // Each footprint's chord goes straight to the render's table; only the reaches are kept
    // for the sweep (6 numbers an object).
    let mut reaches = [LightReach::always(); MAX_OBJECTS];
    for (index, (cone, reach)) in light_cones.iter_mut().zip(reaches.iter_mut()).enumerate().take(count) {
        let footprint = scene.acceleration.light_footprint(index, light);
        *cone = footprint.chord;
        *reach = footprint.reach;
    }
    let mut order = [0u16; MAX_OBJECTS];
    blocker_table(reaches.get(..count).unwrap_or(&[]), &mut order, blockers);
}

#[cfg(not(feature = "acceleration-tables"))]
pub(crate) fn with_shadow_culling<N: Number, R, const MAX_OBJECTS: usize, O: Objects<N>>(
    _scene: &Scene<N, MAX_OBJECTS, O>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    body(&[])
}
