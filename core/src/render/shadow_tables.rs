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
use crate::config::Config;
#[cfg(feature = "acceleration-tables")]
use crate::storage::Table;
use crate::scene::Prepared;

/// Runs `body` with the per-render shadow tables, one per light: for a point light each
/// object's cone of directions from the light, and which objects may shadow which (on the
/// stack: for `f32` about 60 bytes per object and light while a table is built, 32 while `body`
/// runs). Both are built in the number type, in work linear in the objects and their
/// overlapping pairs (`optimize::shadow_culling::blocker_table`). Without the `acceleration-tables`
/// feature there are none.
#[cfg(feature = "acceleration-tables")]
pub(crate) fn with_shadow_culling<N: Number, R, C: Config<Number = N>>(
    scene: &Prepared<C>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    let culls = scene.shadows && scene.acceleration.culls_shadows();
    let objects = if culls { scene.objects.len() } else { 0 };
    let mut light_cones = C::PerObject::<DirectionChord<N>>::filled(objects, DirectionChord::ALWAYS);
    let mut blockers = C::PerObject::<BlockerSet>::filled(objects, BlockerSet::EMPTY);
    let count = objects.min(light_cones.slots().len()).min(blockers.slots().len());
    if culls {
        build_shadow_tables::<N, C>(scene, scene.light, count, light_cones.slots_mut(), blockers.slots_mut());
    }
    let first = culling_of(scene.light, count, light_cones.slots(), blockers.slots());
    if culls && !scene.more_lights.is_empty() {
        return with_more_lights_culling(scene, count, first, body);
    }
    body(&[first])
}

/// The tables of the lights after the first, out of line so that a scene with one light
/// keeps none of their stack.
#[cfg(feature = "acceleration-tables")]
#[inline(never)]
fn with_more_lights_culling<N: Number, R, C: Config<Number = N>>(
    scene: &Prepared<C>,
    count: usize,
    first: ShadowCulling<'_, N>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    const MORE: usize = MAX_LIGHTS - 1;
    // One table of each light after the first, one after the other.
    let mut light_cones = C::PerObjectPerOtherLight::<DirectionChord<N>>::filled(count.saturating_mul(MORE), DirectionChord::ALWAYS);
    let mut blockers = C::PerObjectPerOtherLight::<BlockerSet>::filled(count.saturating_mul(MORE), BlockerSet::EMPTY);
    let per_light = light_cones.slots().len().min(blockers.slots().len()) / MORE;
    if per_light == 0 {
        return body(&[first]);
    }
    for ((source, cones), sets) in scene.more_lights.iter().zip(light_cones.slots_mut().chunks_mut(per_light)).zip(blockers.slots_mut().chunks_mut(per_light)) {
        build_shadow_tables::<N, C>(scene, source.light, count, cones, sets);
    }
    let mut culling = [ShadowCulling::default(); MAX_LIGHTS];
    culling[0] = first;
    for (((slot, source), cones), sets) in culling.iter_mut().skip(1).zip(scene.more_lights.iter()).zip(light_cones.slots().chunks(per_light)).zip(blockers.slots().chunks(per_light)) {
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
fn build_shadow_tables<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    light: PreparedLight<N>,
    count: usize,
    light_cones: &mut [DirectionChord<N>],
    blockers: &mut [BlockerSet],
) {
    let light = match light {
        PreparedLight::Point(position) => LightPosition::Point(position),
        PreparedLight::Direction(direction) => LightPosition::Direction(direction),
    };
    // Each footprint's chord goes straight to the render's table; only the reaches are kept
    // for the sweep (6 numbers an object).
    let mut reaches = C::PerObject::<LightReach<N>>::filled(count, LightReach::always());
    for (index, (cone, reach)) in light_cones.iter_mut().zip(reaches.slots_mut().iter_mut()).enumerate().take(count) {
        let footprint = scene.acceleration.light_footprint(index, light);
        *cone = footprint.chord;
        *reach = footprint.reach;
    }
    let mut order = C::PerObject::<C::Index>::filled(count, C::Index::default());
    blocker_table::<C, N>(reaches.slots().get(..count).unwrap_or(&[]), order.slots_mut(), blockers);
}

#[cfg(not(feature = "acceleration-tables"))]
pub(crate) fn with_shadow_culling<N: Number, R, C: Config<Number = N>>(
    _scene: &Prepared<C>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    body(&[])
}
