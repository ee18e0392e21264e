//! The light's culling tables, built once per render: for each light, each object's cone of
//! directions from it and which objects may shadow which (docs/optimizations.md).

use super::shadow_ray::ShadowCulling;
#[cfg(feature = "acceleration-tables")]
use crate::model::MAX_LIGHTS;
use crate::number::Number;
#[cfg(feature = "acceleration-tables")]
use crate::optimize::shadow_culling::{blocker_table, sweep, BlockerSet, DirectionChord, LightPosition, LightReach};
use crate::optimize::shadow_culling::ShadowTables;
#[cfg(feature = "acceleration-tables")]
use super::shadow_ray::BlockersBeyond;
#[cfg(feature = "acceleration-tables")]
use crate::light::PreparedLight;
use crate::config::Config;
#[cfg(feature = "acceleration-tables")]
use crate::storage::{Index, Table};
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
    body: impl FnOnce(&[ShadowCulling<'_, N, C::Index>]) -> R,
) -> R {
    if !(scene.shadows && scene.acceleration.culls_shadows()) {
        // No tables (and, where the number type cannot cull, none in the frame).
        return body(&[ShadowCulling::NONE]);
    }
    if scene.acceleration.hierarchy().is_some() {
        // The hierarchy finds each shadow ray's few candidates, near the ray already: each
        // light's cones of directions rejected none its capsules would not, and building them,
        // a light per object, cost each render call (each band of a threaded render) about
        // 5 ms on the SPD tree (two threads were slower than one: 287 against 234 ms).
        return body(&[ShadowCulling::NONE]);
    }
    if <C::LightTables<ShadowTables<'static, N>> as Table<_>>::BAKED {
        // Baked for this view and these lights (in flash): nothing is built, and the building
        // code is not linked.
        return with_baked_tables(scene, body);
    }
    let objects = scene.objects.len();
    let mut light_cones = C::PerObject::<DirectionChord<N>>::filled(objects, DirectionChord::ALWAYS);
    let mut blockers = C::PerObject::<BlockerSet>::filled(objects, BlockerSet::EMPTY);
    let count = objects.min(light_cones.slots().len()).min(blockers.slots().len());
    let lists = build_shadow_tables::<N, C>(scene, scene.light, count, light_cones.slots_mut(), blockers.slots_mut());
    let first = culling_of(scene, scene.light, count, light_cones.slots(), blockers.slots(), &lists);
    if !scene.more_lights.is_empty() {
        return with_more_lights_culling(scene, count, first, body);
    }
    body(&[first])
}

/// The culling of each light from its baked tables (`Config::LightTables`); a light without
/// one culls nothing (every object a candidate: the same picture, more tests).
#[cfg(feature = "acceleration-tables")]
fn with_baked_tables<N: Number, R, C: Config<Number = N>>(scene: &Prepared<C>, body: impl FnOnce(&[ShadowCulling<'_, N, C::Index>]) -> R) -> R {
    let tables = scene.acceleration.shadow_tables();
    let mut culling = [ShadowCulling::NONE; MAX_LIGHTS];
    for (slot, table) in culling.iter_mut().zip(tables) {
        *slot = ShadowCulling { light_cones: table.light_cones, blockers: table.blockers, beyond: BlockersBeyond::NONE };
    }
    body(culling.get(..=scene.more_lights.len()).unwrap_or(&culling))
}

/// The lights' shadow tables as a render of `scene` builds them (`with_shadow_culling`), for
/// `body` to bake ([`crate::bake`]); none (an empty slice) where the render builds none. The
/// lists beyond the 128th object (`Config::BLOCKER_LISTS`, a host's) are not among them.
#[cfg(feature = "acceleration-tables")]
pub fn built_shadow_tables<N: Number, R, C: Config<Number = N>>(scene: &Prepared<C>, body: impl FnOnce(&[ShadowTables<'_, N>]) -> R) -> R {
    with_shadow_culling(scene, |culling| {
        let mut tables = [ShadowTables { light_cones: &[], blockers: &[] }; MAX_LIGHTS];
        for (table, light) in tables.iter_mut().zip(culling) {
            *table = ShadowTables { light_cones: light.light_cones, blockers: light.blockers };
        }
        let built = culling.iter().any(|light| !light.light_cones.is_empty() || !light.blockers.is_empty());
        body(if built { tables.get(..culling.len()).unwrap_or(&[]) } else { &[] })
    })
}

#[cfg(not(feature = "acceleration-tables"))]
pub fn built_shadow_tables<N: Number, R, C: Config<Number = N>>(_scene: &Prepared<C>, body: impl FnOnce(&[ShadowTables<'_, N>]) -> R) -> R {
    body(&[])
}

/// The tables of the lights after the first, out of line so that a scene with one light
/// keeps none of their stack.
#[cfg(feature = "acceleration-tables")]
#[inline(never)]
fn with_more_lights_culling<N: Number, R, C: Config<Number = N>>(
    scene: &Prepared<C>,
    count: usize,
    first: ShadowCulling<'_, N, C::Index>,
    body: impl FnOnce(&[ShadowCulling<'_, N, C::Index>]) -> R,
) -> R {
    const MORE: usize = MAX_LIGHTS - 1;
    let more = scene.more_lights.len().clamp(1, MORE);
    // One table of each light after the first, one after the other.
    let mut light_cones = C::PerObjectPerOtherLight::<DirectionChord<N>>::filled(count.saturating_mul(more), DirectionChord::ALWAYS);
    let mut blockers = C::PerObjectPerOtherLight::<BlockerSet>::filled(count.saturating_mul(more), BlockerSet::EMPTY);
    let per_light = light_cones.slots().len().min(blockers.slots().len()) / more;
    if per_light < count {
        return body(&[first]);
    }
    let mut lists: [BlockerLists<C>; MORE] = core::array::from_fn(|_| BlockerLists::none());
    for (((source, cones), sets), lists) in scene.more_lights.iter().zip(light_cones.slots_mut().chunks_mut(per_light)).zip(blockers.slots_mut().chunks_mut(per_light)).zip(lists.iter_mut()) {
        *lists = build_shadow_tables::<N, C>(scene, source.light, count, cones, sets);
    }
    let mut culling = [ShadowCulling::default(); MAX_LIGHTS];
    culling[0] = first;
    for ((((slot, source), cones), sets), lists) in
        culling.iter_mut().skip(1).zip(scene.more_lights.iter()).zip(light_cones.slots().chunks(per_light)).zip(blockers.slots().chunks(per_light)).zip(lists.iter())
    {
        *slot = culling_of(scene, source.light, count, cones, sets, lists);
    }
    body(culling.get(..=scene.more_lights.len()).unwrap_or(&[]))
}

/// The culling of one light from its tables (only a point light has cones; a scene with the
/// hierarchy has no blocker table, every object a candidate for it to find).
#[cfg(feature = "acceleration-tables")]
fn culling_of<'a, N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    light: PreparedLight<N>,
    count: usize,
    light_cones: &'a [DirectionChord<N>],
    blockers: &'a [BlockerSet],
    lists: &'a BlockerLists<C>,
) -> ShadowCulling<'a, N, C::Index> {
    let blockers = if scene.acceleration.hierarchy().is_some() { &[] } else { blockers };
    let cone_count = if matches!(light, PreparedLight::Point(_)) { count } else { 0 };
    let beyond = BlockersBeyond { starts: lists.starts.slots(), entries: lists.entries.slots() };
    ShadowCulling { light_cones: light_cones.get(..cone_count).unwrap_or(&[]), blockers: blockers.get(..count).unwrap_or(&[]), beyond }
}

/// The most blockers from the 128th object on that the lists keep for each object on average
/// (4 bytes each, a light): past it, none are kept.
#[cfg(feature = "acceleration-tables")]
const BLOCKERS_PER_OBJECT_AT_MOST: usize = 32;

/// Each object's blockers from the 128th object on, for [`Config::BLOCKER_LISTS`]
/// ([`BlockersBeyond`]); empty (and nothing at all in an [`crate::config::Arrays`] build) when not kept.
#[cfg(feature = "acceleration-tables")]
pub(crate) struct BlockerLists<C: Config> {
    starts: C::BlockerLists,
    entries: C::BlockerLists,
}

#[cfg(feature = "acceleration-tables")]
impl<C: Config> BlockerLists<C> {
    fn none() -> Self {
        Self { starts: C::BlockerLists::filled(0, C::Index::default()), entries: C::BlockerLists::filled(0, C::Index::default()) }
    }

    /// The lists from the footprints and their order by low x ([`blocker_table`]'s): the sweep
    /// once to count each receiver's blockers, once to place them; each list then sorted, so a
    /// shadow ray meets its candidates in object order as before. None kept (every object from
    /// the 128th on a candidate, as without the lists) once the pairs pass
    /// [`BLOCKERS_PER_OBJECT_AT_MOST`] an object: the counting sweep stops there, so a scene
    /// whose bounds overlap widely pays little for lists it would not gain by (docs/scale.md).
    fn of<N: Number>(reaches: &[LightReach<N>], order: &[C::Index]) -> Self {
        let beyond = |blocker: usize| blocker >= BlockerSet::CAPACITY;
        let count = reaches.len();
        let budget = count.saturating_mul(BLOCKERS_PER_OBJECT_AT_MOST).min(C::Index::MAX);
        let mut starts = C::BlockerLists::filled(count + 1, C::Index::default());
        let places = starts.slots_mut();
        if places.len() <= count {
            return Self::none();
        }
        // Each receiver's count at its successor's place, then the running sums: its start.
        let mut total = 0usize;
        sweep(reaches, order, beyond, |receiver, _| {
            if let Some(place) = places.get_mut(receiver + 1) {
                *place = C::Index::new(place.get() + 1);
            }
            total += 1;
            total <= budget
        });
        if total > budget {
            return Self::none();
        }
        let mut sum = 0;
        for place in places.iter_mut() {
            sum += place.get();
            *place = C::Index::new(sum);
        }
        let mut entries = C::BlockerLists::filled(total, C::Index::default());
        let listed = entries.slots_mut();
        // Each receiver's start moves on as its blockers are placed, ending at the next start.
        sweep(reaches, order, beyond, |receiver, blocker| {
            if let Some(place) = places.get_mut(receiver) {
                if let Some(entry) = listed.get_mut(place.get()) {
                    *entry = C::Index::new(blocker);
                }
                *place = C::Index::new(place.get() + 1);
            }
            true
        });
        places.copy_within(..count, 1);
        if let Some(first) = places.first_mut() {
            *first = C::Index::default();
        }
        for receiver in 0..count {
            if let (Some(start), Some(end)) = (places.get(receiver), places.get(receiver + 1)) {
                if let Some(list) = listed.get_mut(start.get()..end.get()) {
                    list.sort_unstable();
                }
            }
        }
        Self { starts, entries }
    }
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
) -> BlockerLists<C> {
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
    if scene.acceleration.hierarchy().is_some() {
        // The hierarchy finds the blockers: no table over the pairs of objects.
        return BlockerLists::none();
    }
    let mut order = C::PerObject::<C::Index>::filled(count, C::Index::default());
    let reaches = reaches.slots().get(..count).unwrap_or(&[]);
    blocker_table::<C, N>(reaches, order.slots_mut(), blockers);
    if C::BLOCKER_LISTS && count > BlockerSet::CAPACITY {
        BlockerLists::of(reaches, order.slots().get(..count).unwrap_or(&[]))
    } else {
        BlockerLists::none()
    }
}

#[cfg(not(feature = "acceleration-tables"))]
pub(crate) fn with_shadow_culling<N: Number, R, C: Config<Number = N>>(
    _scene: &Prepared<C>,
    body: impl FnOnce(&[ShadowCulling<'_, N, C::Index>]) -> R,
) -> R {
    body(&[])
}
