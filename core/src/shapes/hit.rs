//! What a primitive's intersection returns: the hit, and the nearest (`intersect`) or any
//! (`occluded`) of a primitive's surface crossings.

#[cfg(any(feature = "cone", feature = "cylinder", feature = "frustum"))]
use super::ScaledInterval;
use crate::geometry::Vector3;
#[cfg(any(feature = "cone", feature = "cylinder", feature = "frustum"))]
use crate::number::Number;

/// A hit in object space: the ray parameter and the outward normal there (not normalised).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit<N> {
    pub t: N,
    pub normal: Vector3<N>,
}

/// The nearest of a primitive's crossings (t, normal) inside `interval`; `None` entries are
/// misses.
#[cfg(any(feature = "cone", feature = "cylinder", feature = "frustum"))]
#[inline]
pub(super) fn nearest<N: Number, const K: usize>(crossings: [Option<(N, Vector3<N>)>; K], interval: ScaledInterval<N>) -> Option<Hit<N>> {
    let mut best: Option<Hit<N>> = None;
    for (t, normal) in crossings.into_iter().flatten() {
        if interval.contains(t) && best.is_none_or(|hit| t < hit.t) {
            best = Some(Hit { t, normal });
        }
    }
    best
}

/// Whether any of the crossings is inside `interval`.
#[cfg(any(feature = "cone", feature = "cylinder", feature = "frustum"))]
#[inline]
pub(super) fn any<N: Number, const K: usize>(crossings: [Option<(N, Vector3<N>)>; K], interval: ScaledInterval<N>) -> bool {
    crossings.into_iter().flatten().any(|(t, _)| interval.contains(t))
}
