//! The nearest hit of a secondary ray (reflected or refracted, thesis §5.2.1): a ray that
//! starts anywhere, so the screen-space optimizations do not apply. Every object is a
//! candidate; its bounding sphere (`optimize::bounding_sphere`) is checked before its
//! primitive. The ray's own object is tested too: a refracted ray inside a sphere must find the
//! sphere's far side. Exact ties go to the object that comes first, as for primary rays.

use super::intersect::NearestHit;
use super::intersect::hit_object;
use super::Statistics;
use crate::geometry::Ray;
use crate::number::Number;
use crate::config::Config;
use crate::scene::Prepared;
use crate::shapes::Interval;

pub(crate) fn nearest_secondary_hit<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    ray: &Ray<N>,
    statistics: &mut Statistics,
) -> Option<NearestHit<N>> {
    #[cfg(feature = "acceleration-tables")]
    if let Some(hierarchy) = scene.acceleration.hierarchy() {
        return nearest_in_hierarchy(scene, &hierarchy, ray, statistics);
    }
    if scene.space_grid.is_built() {
        return nearest_in_grid(scene, ray, statistics);
    }
    let mut nearest: Option<NearestHit<N>> = None;
    for (index, object) in scene.objects.iter().enumerate() {
        let reach = nearest.map_or(N::MAX, |best| best.t);
        if !scene.bounding_sphere(index).may_meet(ray.origin, ray.direction, reach) {
            continue;
        }
        // Objects come in order, so an equal t never replaces an earlier object.
        let interval = nearest.map_or(Interval::unbounded(), |best| Interval::below(best.t));
        statistics.secondary_tests += 1;
        if let Some(hit) = hit_object(scene, index, object, ray, &object.object_from_world.ray(ray), interval, None, statistics) {
            nearest = Some(hit);
        }
    }
    nearest
}

/// [`nearest_secondary_hit`] through the hierarchy of boxes of a scene of many objects
/// (`optimize::bvh`): the objects of the boxes along the ray, nearer boxes first and none
/// beyond the nearest hit; ties still go to the earlier object.
#[cfg(feature = "acceleration-tables")]
fn nearest_in_hierarchy<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    hierarchy: &crate::optimize::bvh::Bvh<'_, N, C::Index>,
    ray: &Ray<N>,
    statistics: &mut Statistics,
) -> Option<NearestHit<N>> {
    use crate::optimize::bvh::Walk;
    let mut nearest: Option<NearestHit<N>> = None;
    hierarchy.walk(ray.origin, ray.direction, N::MAX, |index| {
        consider(scene, ray, index, &mut nearest, statistics);
        nearest.map_or(Walk::On, |best| Walk::Within(best.t))
    });
    nearest
}

/// [`nearest_secondary_hit`] through the uniform 3-D grid: only the objects of the cells the ray
/// passes, in the cells' order; ties still go to the earlier object.
fn nearest_in_grid<N: Number, C: Config<Number = N>>(scene: &Prepared<C>, ray: &Ray<N>, statistics: &mut Statistics) -> Option<NearestHit<N>> {
    let mut nearest: Option<NearestHit<N>> = None;
    scene.space_grid.walk(ray, scene.objects.len(), |index| {
        consider(scene, ray, index, &mut nearest, statistics);
        nearest.map(|best| best.t)
    });
    nearest
}

/// One candidate of a walk that meets objects in no particular order: tested when its bounding
/// sphere lets the ray through short of the nearest hit, and the nearer hit kept; a hit at the
/// nearest `t` so far replaces it only for an earlier object (ties to the earlier object, as in
/// object order).
#[inline(always)]
fn consider<N: Number, C: Config<Number = N>>(scene: &Prepared<C>, ray: &Ray<N>, index: usize, nearest: &mut Option<NearestHit<N>>, statistics: &mut Statistics) {
    let reach = nearest.map_or(N::MAX, |best| best.t);
    let Some(object) = scene.objects.get(index) else { return };
    if !scene.bounding_sphere(index).may_meet(ray.origin, ray.direction, reach) {
        return;
    }
    let interval = match *nearest {
        None => Interval::unbounded(),
        Some(best) => Interval { max: best.t, include_max: index < best.object },
    };
    statistics.secondary_tests += 1;
    if let Some(hit) = hit_object(scene, index, object, ray, &object.object_from_world.ray(ray), interval, None, statistics) {
        *nearest = Some(hit);
    }
}
