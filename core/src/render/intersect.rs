//! A ray against one object of the scene: a primitive in its own space (`shapes`), or a solid
//! through its operands' spans (`csg::solid`, thesis §3.3). Every ray of the render (primary,
//! shadow, secondary) meets objects here, so a solid is a solid to each of them.

use super::Statistics;
use crate::config::Config;
use crate::camera::PixelPosition;
use crate::geometry::{Ray, Vector3};
use crate::model::Object;
use crate::number::Number;
use crate::scene::Prepared;
use crate::shapes::Interval;

/// A ray's nearest hit on an object of the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NearestHit<N> {
    pub object: usize,
    pub t: N,
    /// Object-space normal, not normalised (for a solid, in the space of the leaf hit).
    pub local_normal: Vector3<N>,
    /// For a solid, the leaf whose surface was hit (its place among the solid's nodes); else
    /// `NO_LEAF`.
    #[cfg(feature = "csg")]
    pub leaf: u16,
}

/// The surface a hit is on when it is not a solid's leaf.
#[cfg(feature = "csg")]
pub const NO_LEAF: u16 = u16::MAX;

/// The nearest hit on `object` (number `index`) inside `interval`: `world` is the ray, `local`
/// the same in the object's space (a primitive's; a solid works from `world`), `pixel` a
/// primary ray's (inside a solid, Extents skips the parts whose extent excludes it). The caller
/// makes `local` as it always did: made here, behind the solid's branch, it cost the
/// Cortex-M4F's unoptimized snooker frame 14 % (the transform no longer inlined).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn hit_object<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    index: usize,
    object: &Object<N>,
    world: &Ray<N>,
    local: &Ray<N>,
    interval: Interval<N>,
    pixel: Option<PixelPosition>,
    statistics: &mut Statistics,
) -> Option<NearestHit<N>> {
    #[cfg(feature = "csg")]
    if let crate::model::Primitive::Solid(_) = object.primitive {
        // A primary ray with Extents on skips each part of the solid whose extent excludes its
        // pixel (§3.3.6).
        let acceleration = &scene.acceleration;
        let pixel = pixel.filter(|_| acceleration.optimizations().extents);
        let height = acceleration.screen().height;
        let prune = |extent: &crate::model::Extent| pixel.is_some_and(|pixel| !extent.covers(pixel.column, pixel.row, height));
        let hit = crate::csg::first_hit::<N, C::Solids>(scene.solid(object.primitive), world, interval, prune, &mut statistics.solid_leaf_tests)?;
        return Some(NearestHit { object: index, t: hit.t, local_normal: hit.normal, leaf: hit.leaf });
    }
    #[cfg(not(feature = "csg"))]
    let _ = (scene, world, pixel, statistics);
    let hit = object.primitive.intersect(local, interval)?;
    Some(NearestHit {
        object: index,
        t: hit.t,
        local_normal: hit.normal,
        #[cfg(feature = "csg")]
        leaf: NO_LEAF,
    })
}

/// Whether `object` blocks the ray anywhere inside `interval` (a shadow ray).
#[inline(always)]
pub(crate) fn object_occludes<N: Number, C: Config<Number = N>>(scene: &Prepared<C>, object: &Object<N>, world: &Ray<N>, interval: Interval<N>, statistics: &mut Statistics) -> bool {
    #[cfg(feature = "csg")]
    if let crate::model::Primitive::Solid(_) = object.primitive {
        return crate::csg::occluded::<N, C::Solids>(scene.solid(object.primitive), world, interval, &mut statistics.solid_leaf_tests);
    }
    #[cfg(not(feature = "csg"))]
    let _ = (scene, statistics);
    object.primitive.occluded(&object.object_from_world.ray(world), interval)
}

/// The object whose transform and material the hit's surface has: the object hit, or for a
/// solid the leaf whose surface it is.
#[inline(always)]
pub(crate) fn surface_of<'a, N: Number, C: Config<Number = N>>(scene: &'a Prepared<C>, hit: &NearestHit<N>) -> Option<&'a Object<N>> {
    let object = scene.objects.get(hit.object)?;
    #[cfg(feature = "csg")]
    if let Some(crate::model::PreparedSolidNode::Leaf { object: leaf, .. }) = scene.solid(object.primitive).get(usize::from(hit.leaf)) {
        return Some(leaf);
    }
    Some(object)
}
