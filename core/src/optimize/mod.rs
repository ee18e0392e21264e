//! The four screen-space optimizations for primary rays (§4.7): Pixelbuffer, Extents, Grid and
//! Sortlist. Each only skips work whose result is known, so every combination renders the same
//! image as none.

use crate::camera::{Camera, PixelPosition};
use crate::number::Number;
use crate::scene::{ObjectDescription, Optimizations};

/// What the optimizations derive from the objects' bounding volumes at preprocess time.
#[derive(Debug, Clone)]
pub struct Acceleration<N, const MAX_OBJECTS: usize> {
    object_count: usize,
    _number: core::marker::PhantomData<N>,
}

impl<N: Number, const MAX_OBJECTS: usize> Acceleration<N, MAX_OBJECTS> {
    pub fn build(_camera: &Camera<N>, _optimizations: Optimizations, objects: &[ObjectDescription]) -> Self {
        Self { object_count: objects.len().min(MAX_OBJECTS), _number: core::marker::PhantomData }
    }

    /// The objects a primary ray through `pixel` must be tested against, in test order.
    pub fn candidates(&self, _pixel: PixelPosition) -> impl Iterator<Item = usize> + '_ {
        0..self.object_count
    }
}
