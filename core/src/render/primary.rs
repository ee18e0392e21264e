//! The nearest hit of a primary ray (the loop of `raycast`, digest §4.8), with the
//! optimizations: Grid picks the candidate list, Extents skips candidates whose rectangle
//! excludes the pixel (checked first, as in the thesis), Sortlist ends the loop once the next
//! candidate's depth bound exceeds the nearest hit.
//!
//! Exact ties go to the object that comes first in the scene, whatever order the candidates
//! are tested in, so reordering optimizations (Grid, Sortlist) cannot change the image; the
//! thesis gave ties to whichever was tested first (digest §12).

use super::intersect::{hit_object, NearestHit};
use super::Statistics;
use crate::camera::PixelPosition;
use crate::geometry::{Ray, Vector3};
use crate::number::Number;
use crate::optimize::grid::entry_covers;
use crate::config::Config;
use crate::storage::Index;
use crate::model::Object;
use crate::scene::Prepared;
use crate::shapes::Interval;

/// The primary ray `ray` in the object's space: for a perspective view from `eye`, the eye in
/// object space prepared with the scene ([`Scene::eyes`]; the same bits as
/// `object_from_world.ray(ray)`, one transform fewer per test).
#[inline(always)]
fn local_ray<N: Number>(object: &Object<N>, eye: Option<&Vector3<N>>, ray: &Ray<N>) -> Ray<N> {
    match eye {
        Some(eye) => Ray { origin: *eye, direction: object.object_from_world.vector(ray.direction) },
        None => object.object_from_world.ray(ray),
    }
}

/// The nearest hit of a primary ray (one from `scene.camera.primary_ray`).
pub fn nearest_hit<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    ray: &Ray<N>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
) -> Option<NearestHit<N>> {
    nearest_hit_cached(scene, ray, pixel, statistics, &mut None)
}

/// [`nearest_hit`], first testing `last_hit` (the object the previous ray hit, updated here)
/// when the acceleration uses the hit cache. Which objects are tested first cannot change the
/// result: ties go by object number, and Sortlist's exit only skips objects whose bound lies
/// beyond the nearest hit. Always inline: out of line, its hit returns through memory.
#[inline(always)]
pub fn nearest_hit_cached<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    ray: &Ray<N>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
    last_hit: &mut Option<C::Index>,
) -> Option<NearestHit<N>> {
    let acceleration = &scene.acceleration;
    let from_eye = scene.camera.eye().is_some();
    let mut nearest: Option<NearestHit<N>> = None;
    let cached = if acceleration.uses_hit_cache() { last_hit.map(Index::get).filter(|i| acceleration.in_extent(*i, pixel)) } else { None };
    if let Some(index) = cached {
        // Tested unbounded, before anything else: its result is final, so the loop skips it.
        if let Some(object) = scene.objects.get(index) {
            statistics.ro_tests += 1;
            if let Some(hit) = hit_object(scene, index, object, ray, &local_ray(object, scene.eyes().get(index).filter(|_| from_eye), ray), Interval::unbounded(), Some(pixel), statistics) {
                statistics.ro_hits += 1;
                nearest = Some(hit);
            }
        }
    }
    // Tests one candidate; false ends the loop (Sortlist's exit). Forced inline at both
    // sites: a call per candidate cost more than the extent checks it makes.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn test<N: Number, C: Config<Number = N>>(
        scene: &Prepared<C>,
        ray: &Ray<N>,
        pixel: PixelPosition,
        from_eye: bool,
        cached: Option<usize>,
        statistics: &mut Statistics,
        index: usize,
        nearest: &mut Option<NearestHit<N>>,
    ) -> bool {
        let acceleration = &scene.acceleration;
        if Some(index) == cached {
            return true;
        }
        if acceleration.outside_extent(index, pixel) {
            return true;
        }
        let interval = match *nearest {
            None => Interval::unbounded(),
            Some(best) => {
                if acceleration.beyond(index, best.t) {
                    return false;
                }
                // An equal t wins only for an object earlier in the scene.
                Interval { max: best.t, include_max: index < best.object }
            }
        };
        let Some(object) = scene.objects.get(index) else { return true };
        statistics.ro_tests += 1;
        if let Some(hit) = hit_object(scene, index, object, ray, &local_ray(object, scene.eyes().get(index).filter(|_| from_eye), ray), interval, Some(pixel), statistics) {
            statistics.ro_hits += 1;
            *nearest = Some(hit);
        }
        true
    }
    if let Some((entries, depths, dx, dy)) = acceleration.grid_cell(pixel) {
        let sorts = acceleration.sorts();
        for (position, entry) in entries.iter().enumerate() {
            if !entry_covers(entry, dx, dy) {
                continue;
            }
            // The cell list is sorted by these bounds: once one exceeds the nearest hit, so do
            // all later ones (strictly, so an equal t is still tested).
            if sorts {
                if let (Some(best), Some(depth)) = (nearest, depths.get(position)) {
                    if *depth > best.t {
                        break;
                    }
                }
            }
            if !test(scene, ray, pixel, from_eye, cached, statistics, entry.object.get(), &mut nearest) {
                break;
            }
        }
    } else {
        for &index in acceleration.order() {
            if !test(scene, ray, pixel, from_eye, cached, statistics, index.get(), &mut nearest) {
                break;
            }
        }
    }
    if let Some(hit) = nearest {
        *last_hit = Some(C::Index::new(hit.object));
    }
    nearest
}
