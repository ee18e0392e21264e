//! The nearest hit of a primary ray (the loop of `raycast`, digest §4.8), with the
//! optimizations: Grid picks the candidate list, Extents skips candidates whose rectangle
//! excludes the pixel (checked first, as in the thesis), Sortlist ends the loop once the next
//! candidate's depth bound exceeds the nearest hit.
//!
//! Exact ties go to the object that comes first in the scene, whatever order the candidates
//! are tested in, so reordering optimizations (Grid, Sortlist) cannot change the image; the
//! thesis gave ties to whichever was tested first (digest §12).

use super::Statistics;
use crate::camera::PixelPosition;
use crate::geometry::{Ray, Vector3};
use crate::number::Number;
use crate::scene::Scene;
use crate::shapes::Interval;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NearestHit<N> {
    pub object: usize,
    pub t: N,
    /// Object-space normal, not normalised.
    pub local_normal: Vector3<N>,
}

pub fn nearest_hit<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    ray: &Ray<N>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
) -> Option<NearestHit<N>> {
    let acceleration = &scene.acceleration;
    let mut nearest: Option<NearestHit<N>> = None;
    for &candidate in acceleration.candidates(pixel) {
        let index = usize::from(candidate);
        if acceleration.outside_extent(index, pixel) {
            continue;
        }
        let interval = match nearest {
            None => Interval::unbounded(),
            Some(best) => {
                if acceleration.beyond(index, best.t) {
                    break;
                }
                // An equal t wins only for an object earlier in the scene.
                Interval { max: best.t, include_max: index < best.object }
            }
        };
        let Some(object) = scene.objects.get(index) else { continue };
        statistics.ro_tests += 1;
        let local_ray = object.object_from_world.ray(ray);
        if let Some(hit) = object.primitive.intersect(&local_ray, interval) {
            statistics.ro_hits += 1;
            nearest = Some(NearestHit { object: index, t: hit.t, local_normal: hit.normal });
        }
    }
    nearest
}
