//! One object as written: a primitive, its transform and its material (§4.2.5), in `f64`.

use super::{Material, Primitive};
use crate::geometry::Matrix4;

/// One object: a primitive instanced by a transform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjectDescription {
    pub primitive: Primitive,
    /// Local -> world, composed from the object's statements in order.
    pub world_from_object: Matrix4,
    pub material: Material,
    /// The line of the `.mts` file where the object starts (0 when not from a file), so that
    /// later checks can name it.
    pub line: u32,
}

impl ObjectDescription {
    pub fn new(primitive: Primitive, line: u32) -> Self {
        Self { primitive, world_from_object: Matrix4::IDENTITY, material: Material::default(), line }
    }
}
