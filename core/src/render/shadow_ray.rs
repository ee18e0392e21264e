//! Shadow rays (`inshadow`, digest §4.7 and §5): from the hit point toward the light, bounded
//! by the light's distance for a point light. The shaded object itself is skipped: a convex
//! closed primitive cannot shadow its own lit side, and skipping it makes a surface shadowing
//! itself impossible without any epsilon. A coincident or touching object's surface passes
//! through the hit point too, and rounding puts the point on either side of it; so the ray
//! starts a little off the surface ([`shadow_origin`], docs/hard-cases.md).
//!
//! Beyond the thesis (which tested every other object): an object is tested only when the
//! shadow ray's segment passes through its bounding sphere (`optimize::shadow_culling`), and the object
//! that blocked the previous shadow ray is tried first (a shadow cache). Both only skip tests
//! whose answer is known or reorder tests of a yes/no question, so the image is unchanged.
//! They are on with Extents (they are its three-dimensional counterpart) unless the
//! acceleration was built with the thesis's tuning.

use super::Statistics;
use crate::geometry::{Ray, Vector3};
use crate::number::Number;
use crate::optimize::shadow_culling::{BlockerSet, DirectionChord, QuantizedDirection};
use crate::model::MAX_LIGHTS;
use crate::config::Config;
use crate::storage::Index;
use crate::scene::Prepared;
#[cfg(test)]
use crate::light::PreparedLight;
use crate::shapes::Interval;

/// How far off the surface a shadow ray starts, as a power of two of the hit point's largest
/// coordinate (plus one): 2⁻¹⁷. Hundreds of times the rounding of a computed hit point in
/// `f32` and Q32.32 (hard cases: no acne on coincident faces), far below a pixel.
const OFFSET_EXPONENT: i32 = -17;

/// Fixed point's rounding is absolute as well: at least 2^this steps of its resolution (16).
const RESOLUTION_STEPS_EXPONENT: i32 = 4;

/// Where a shadow ray starts: `point` moved along the unit `normal` (which faces the light when
/// a shadow ray is traced) by 2^`OFFSET_EXPONENT` of its magnitude, plus 16 steps of a
/// fixed-point type's resolution.
pub fn shadow_origin<N: Number>(point: Vector3<N>, normal: Vector3<N>) -> Vector3<N> {
    let magnitude = point.largest_component() + N::ONE;
    let offset = magnitude.times_power_of_two(OFFSET_EXPONENT) + N::RESOLUTION.times_power_of_two(RESOLUTION_STEPS_EXPONENT);
    point + normal * offset
}

/// The object that blocked the last shadow ray, tried first by the next one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ShadowCache<I> {
    pub last_blocker: Option<I>,
    /// The object the last primary ray hit (see `nearest_hit_cached`).
    pub last_hit: Option<I>,
    /// The last blocker of each further light's shadow rays.
    pub more_blockers: [Option<I>; MAX_LIGHTS - 1],
}

pub fn in_shadow<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
) -> bool {
    in_shadow_cached(scene, shaded_object, point, to_light, light_distance, statistics, &mut ShadowCache::default())
}

pub fn in_shadow_cached<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
) -> bool {
    in_shadow_culled(scene, shaded_object, point, to_light, light_distance, statistics, cache, &ShadowCulling::default())
}

/// Per-render shadow culling data, indexed by object (empty slices: none).
#[derive(Clone, Copy, Debug)]
pub struct ShadowCulling<'a, N, I> {
    /// For a point light: each object's cone of directions from the light.
    pub light_cones: &'a [DirectionChord<N>],
    /// For each receiving object, the objects among the first 128 that may shadow it; objects
    /// from 128 on are candidates unless `beyond` lists them.
    pub blockers: &'a [BlockerSet],
    /// Where the host keeps them (`Config::BLOCKER_LISTS`): for each receiving object, the
    /// objects from 128 on that may shadow it, in ascending order (`render/shadow_tables.rs`).
    pub beyond: BlockersBeyond<'a, I>,
}

/// The objects from 128 on that may shadow each receiver: receiver `r`'s are
/// `entries[starts[r]..starts[r + 1]]` (empty `starts`: not kept, every one is a candidate).
#[derive(Clone, Copy, Debug)]
pub struct BlockersBeyond<'a, I> {
    pub starts: &'a [I],
    pub entries: &'a [I],
}

impl<'a, I: Index> BlockersBeyond<'a, I> {
    pub const NONE: Self = Self { starts: &[], entries: &[] };

    /// The receiver's list, or `None` when the lists are not kept.
    #[inline]
    pub fn of(&self, receiver: usize) -> Option<&'a [I]> {
        let (start, end) = (self.starts.get(receiver)?, self.starts.get(receiver + 1)?);
        self.entries.get(start.get()..end.get())
    }
}

impl<N, I: Index> ShadowCulling<'_, N, I> {
    /// No culling: every object is a candidate.
    pub const NONE: Self = Self { light_cones: &[], blockers: &[], beyond: BlockersBeyond::NONE };
}

impl<N, I: Index> Default for ShadowCulling<'_, N, I> {
    fn default() -> Self {
        Self::NONE
    }
}

/// [`in_shadow_cached`] with, for a point light, each object's cone of directions from the light
/// (`ShadowBound::light_cone`, indexed by object; empty: none), checked before its capsule.
#[allow(clippy::too_many_arguments)]
pub fn in_shadow_culled<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
    culling: &ShadowCulling<'_, N, C::Index>,
) -> bool {
    blocked(scene, shaded_object, point, to_light, light_distance, statistics, &mut cache.last_blocker, culling)
}

/// The share of a light that reaches `point` on `shaded_object` (chapter 5): one when nothing
/// blocks the shadow ray, zero when an opaque object does, else the product of the
/// transparent blockers' `transmit` (shadow rays are not refracted, as the thesis says). In
/// a scene without transparent objects, [`in_shadow_culled`]'s yes or no.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn light_share<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
    last_blocker: &mut Option<C::Index>,
    culling: &ShadowCulling<'_, N, C::Index>,
) -> N {
    #[cfg(feature = "ray-tree")]
    if scene.has_transparent_objects() {
        return transmitted(scene, shaded_object, point, to_light, light_distance, statistics, last_blocker, culling);
    }
    if blocked(scene, shaded_object, point, to_light, light_distance, statistics, last_blocker, culling) { N::ZERO } else { N::ONE }
}

/// [`light_share`] with transparent objects: every candidate is tested (an opaque blocker
/// ends the loop), in object order, so the product is the same whatever the optimizations.
/// The opaque object that last blocked this light's ray is tried first, and through the
/// hierarchy any opaque blocker ends the walk: a zero factor makes the product zero in any
/// order.
#[cfg(feature = "ray-tree")]
#[allow(clippy::too_many_arguments)]
fn transmitted<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
    last_blocker: &mut Option<C::Index>,
    culling: &ShadowCulling<'_, N, C::Index>,
) -> N {
    statistics.shadow_rays += 1;
    let segment = ShadowSegment { ray: Ray { origin: point, direction: to_light }, interval: Interval::below(light_distance) };
    let culls = scene.acceleration.culls_shadows();
    let from_light = -to_light;
    let quantized = if culling.light_cones.is_empty() { QuantizedDirection::default() } else { QuantizedDirection::new(from_light) };
    let set = culling.blockers.get(shaded_object).copied();
    // A scene of many objects: its blockers from the hierarchy, multiplied in object order as
    // below (so the product rounds the same); more than the list holds, the loop below.
    #[cfg(feature = "acceleration-tables")]
    if let Some(hierarchy) = scene.acceleration.hierarchy().filter(|_| culls) {
        let meets = |index: usize, statistics: &mut Statistics| candidate_meets(scene, &segment, culling.light_cones, (from_light, quantized), index, statistics);
        if let Some(index) = last_blocker.map(Index::get).filter(|index| *index != shaded_object) {
            if meets(index, statistics) {
                return N::ZERO;
            }
        }
        let mut blockers: heapless::Vec<usize, 64> = heapless::Vec::new();
        let (mut overflow, mut opaque) = (false, false);
        hierarchy.visit(point, to_light, light_distance, |index| {
            // An object in several leaves (`early_split`) counts once.
            if index != shaded_object && !blockers.contains(&index) && meets(index, statistics) {
                if scene.transmit(index) == N::ZERO {
                    *last_blocker = Some(C::Index::new(index));
                    opaque = true;
                } else if blockers.push(index).is_err() {
                    overflow = true;
                }
            }
            overflow || opaque
        });
        if opaque {
            return N::ZERO;
        }
        if !overflow {
            // In object order, each time the least above the last (a slice's sort links a
            // panic path on the chip; the list is short).
            let (mut share, mut last) = (N::ONE, None);
            while let Some(index) = blockers.iter().copied().filter(|index| last.is_none_or(|last| *index > last)).min() {
                last = Some(index);
                share = share * scene.transmit(index);
                if share == N::ZERO {
                    break;
                }
            }
            return share;
        }
    }
    let mut share = N::ONE;
    for index in 0..scene.objects.len() {
        if index == shaded_object {
            continue;
        }
        let meets = if culls {
            let listed = set.is_none_or(|set| index >= BlockerSet::CAPACITY || set.contains(index));
            listed && candidate_meets(scene, &segment, culling.light_cones, (from_light, quantized), index, statistics)
        } else {
            segment.meets(scene, index, statistics)
        };
        if meets {
            share = share * scene.transmit(index);
            if share == N::ZERO {
                break;
            }
        }
    }
    share
}

/// Whether anything blocks the shadow ray (the thesis's `inshadow`), with the culling and
/// `last_blocker` (the light's shadow cache, tried first and updated).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn blocked<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    shaded_object: usize,
    point: Vector3<N>,
    to_light: Vector3<N>,
    light_distance: N,
    statistics: &mut Statistics,
    last_blocker: &mut Option<C::Index>,
    culling: &ShadowCulling<'_, N, C::Index>,
) -> bool {
    statistics.shadow_rays += 1;
    let segment = ShadowSegment { ray: Ray { origin: point, direction: to_light }, interval: Interval::below(light_distance) };
    if !scene.acceleration.culls_shadows() {
        // The thesis's loop: every other object, in order.
        return (0..scene.objects.len()).any(|index| index != shaded_object && segment.meets(scene, index, statistics));
    }
    let from_light = -to_light;
    let cones = culling.light_cones;
    // Converted once for the candidates' boxes (only a point light has chords). Converting
    // at the first candidate that needs it measured slower: the state kept the candidate
    // test out of line.
    let quantized = if cones.is_empty() { QuantizedDirection::default() } else { QuantizedDirection::new(from_light) };
    let set = culling.blockers.get(shaded_object).copied();
    let listed = |index: usize| set.is_none_or(|set| index >= BlockerSet::CAPACITY || set.contains(index));
    // The last blocker first (never the shaded object: it cannot block its own ray).
    let first = last_blocker.map(Index::get).filter(|index| *index != shaded_object && listed(*index));
    if let Some(index) = first {
        if candidate_meets(scene, &segment, cones, (from_light, quantized), index, statistics) {
            return true;
        }
    }
    let skip = |index: usize| index == shaded_object || Some(index) == first;
    if let Some(set) = set {
        for (word_index, word) in set.words().into_iter().enumerate() {
            let mut remaining = word;
            while remaining != 0 {
                let index = 32 * word_index + remaining.trailing_zeros() as usize;
                remaining &= remaining - 1;
                if !skip(index) && candidate_meets(scene, &segment, cones, (from_light, quantized), index, statistics) {
                    *last_blocker = Some(C::Index::new(index));
                    return true;
                }
            }
        }
    }
    // Only a `Config` that keeps the lists compiles this in (the firmware's does not).
    if let (true, Some(_), Some(listed)) = (C::BLOCKER_LISTS, set, culling.beyond.of(shaded_object)) {
        for index in listed.iter().map(|index| index.get()) {
            if !skip(index) && candidate_meets(scene, &segment, cones, (from_light, quantized), index, statistics) {
                *last_blocker = Some(C::Index::new(index));
                return true;
            }
        }
        return false;
    }
    // A scene of many objects: the objects in the hierarchy's boxes along the ray (the same
    // blockers, far fewer looked at; `optimize::bvh`).
    #[cfg(feature = "acceleration-tables")]
    if let Some(hierarchy) = scene.acceleration.hierarchy() {
        let mut blocker = None;
        let found = hierarchy.any(point, to_light, light_distance, |index| {
            let meets = listed(index) && !skip(index) && candidate_meets(scene, &segment, cones, (from_light, quantized), index, statistics);
            if meets {
                blocker = Some(index);
            }
            meets
        });
        if let Some(index) = blocker {
            *last_blocker = Some(C::Index::new(index));
        }
        return found;
    }
    let start = if set.is_some() { BlockerSet::CAPACITY } else { 0 };
    for index in start..scene.objects.len() {
        if !skip(index) && candidate_meets(scene, &segment, cones, (from_light, quantized), index, statistics) {
            *last_blocker = Some(C::Index::new(index));
            return true;
        }
    }
    false
}

/// Whether a candidate blocks the shadow ray: its chord of directions from the light (a box in
/// integers first, which rejects most), then its capsule and primitive. The chord test is a few
/// multiplications and rejects almost every candidate: forced inline at each site. The capsule
/// test and the primitive's are out of line.
#[inline(always)]
fn candidate_meets<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    segment: &ShadowSegment<N>,
    cones: &[DirectionChord<N>],
    (from_light, quantized): (Vector3<N>, QuantizedDirection),
    index: usize,
    statistics: &mut Statistics,
) -> bool {
    !cones.get(index).is_some_and(|chord| chord.outside_box(quantized) || chord.excludes(from_light)) && segment.may_meet_and_meets(scene, index, statistics)
}

/// A shadow ray's segment: from the (offset) hit point toward the light, up to its distance.
struct ShadowSegment<N> {
    ray: Ray<N>,
    interval: Interval<N>,
}

impl<N: Number> ShadowSegment<N> {
    /// Whether the object's capsule lets the segment through, else whether its primitive does.
    #[inline(never)]
    fn may_meet_and_meets<C: Config<Number = N>>(&self, scene: &Prepared<C>, index: usize, statistics: &mut Statistics) -> bool {
        scene.acceleration.may_shadow(index, self.ray.origin, self.ray.direction, self.interval.max) && self.meets(scene, index, statistics)
    }

    /// The shadow test proper (`occluded` in the object's space), counted.
    fn meets<C: Config<Number = N>>(&self, scene: &Prepared<C>, index: usize, statistics: &mut Statistics) -> bool {
        let Some(object) = scene.objects.get(index) else { return false };
        statistics.shadow_tests += 1;
        super::intersect::object_occludes(scene, object, &self.ray, self.interval, statistics)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parser::parse;

    /// Two coincident spheres: the surface point of one lies on the other too, and rounding puts
    /// it inside or outside. Started off the surface, the shadow ray never meets the twin.
    fn coincident_twin_never_shadows<N: Number>() {
        let text = b"light direction 0.3 0.4 1\nshadows on\nsphere\n  scale 6 6 6\n  translate -8 8 0\nsphere\n  scale 6 6 6\n  translate -8 8 0\n";
        let description = parse::<2>(text).unwrap();
        let scene = crate::scene::Scene::<N, 2>::prepare(&description).unwrap();
        let PreparedLight::Direction(to_light) = scene.light else { unreachable!() };
        let mut shadowed = 0;
        for step in 0..200 {
            let angle = f64::from(step) * 0.0314;
            let normal = [0.3 + 0.5 * libm::cos(angle), 0.4 + 0.5 * libm::sin(angle), 1.0];
            let length = libm::sqrt(normal.iter().map(|c| c * c).sum::<f64>());
            let normal = normal.map(|c| c / length);
            let point = Vector3::<N>::from_f64([-8.0 + 6.0 * normal[0], 8.0 + 6.0 * normal[1], 6.0 * normal[2]]);
            let origin = shadow_origin(point, Vector3::from_f64(normal));
            shadowed += usize::from(in_shadow(&scene, 0, origin, to_light, N::MAX, &mut Statistics::default()));
        }
        assert_eq!(shadowed, 0, "{}", N::NAME);
    }

    #[test]
    fn coincident_surfaces_do_not_shadow_each_other() {
        coincident_twin_never_shadows::<f64>();
        coincident_twin_never_shadows::<f32>();
        #[cfg(feature = "fixed-point")]
        {
            coincident_twin_never_shadows::<crate::number::Fixed>();
            // Q16.16's rounding is absolute: the offset's 16 steps of resolution cover it.
            coincident_twin_never_shadows::<crate::number::Fixed16>();
        }
    }

    #[test]
    fn the_offset_is_tiny_and_along_the_normal() {
        let point = Vector3::<f64>::from_f64([100.0, -3.0, 2.0]);
        let origin = shadow_origin(point, Vector3::from_f64([0.0, 1.0, 0.0]));
        assert_eq!((origin.x, origin.z), (100.0, 2.0));
        assert!(origin.y > -3.0 && origin.y - -3.0 < 101.0 / 131072.0 * 1.000_001, "{}", origin.y);
    }
}
