//! The nearest hit of a primary ray (the loop of `raycast`, digest §4.8).
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
    let mut nearest: Option<NearestHit<N>> = None;
    for index in scene.acceleration.candidates(pixel) {
        let Some(object) = scene.objects.get(index) else { continue };
        let interval = match nearest {
            None => Interval::unbounded(),
            // An equal t wins only for an object earlier in the scene.
            Some(best) => Interval { max: best.t, include_max: index < best.object },
        };
        statistics.ro_tests += 1;
        let local_ray = object.object_from_world.ray(ray);
        if let Some(hit) = object.primitive.intersect(&local_ray, interval) {
            statistics.ro_hits += 1;
            nearest = Some(NearestHit { object: index, t: hit.t, local_normal: hit.normal });
        }
    }
    nearest
}
