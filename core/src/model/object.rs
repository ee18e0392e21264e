//! One object as the tracer needs it, in a number type: the primitive, world -> object, and
//! the material (§4.7 `preprocess`); and where a prepared scene's objects live.

use core::ops::Deref;

use super::{PreparedMaterial, Primitive};
use crate::geometry::AffineTransform;

/// Where a prepared scene's objects live: anything that reads as a slice of them. The host's
/// scene owns them (`heapless::Vec`, the default, prepared from a description); the firmware's
/// reads them in flash, where its build baked them (`OBJECTS`, `crate::bake`), so that they
/// take no RAM: only what depends on the view (each object's eye) is in RAM.
pub trait Objects<N>: Deref<Target = [Object<N>]> {}

impl<N, T: Deref<Target = [Object<N>]>> Objects<N> for T {}

/// One object as the tracer needs it: the primitive, world -> object, and the material.
/// The forward transform is not kept: only the inverse is used per ray, and normals go back
/// through its transpose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Object<N> {
    pub primitive: Primitive,
    pub object_from_world: AffineTransform<N>,
    pub material: PreparedMaterial<N>,
}
