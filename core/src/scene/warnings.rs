//! What a scene that parses and prepares may still get wrong in the picture: no light of its
//! own, the eye inside an object, a point light inside an opaque object. Not errors (each can
//! be meant: a room seen from inside is a sphere around the eye), so the command line warns
//! and renders (`microtrace render`), naming the line.

use core::fmt;
use core::ops::Deref;

use crate::geometry::Vector3;
use crate::model::{Description, Light, ObjectDescription, Primitive, Projection};

/// One thing a scene's picture may not show as its author meant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum SceneWarning {
    /// No `light` statement: the format's default light (a direction, 1 1 1) or, for NFF, a
    /// lamp at the eye lights the scene.
    NoLight,
    /// The scene has no objects: the picture is the background.
    NoObjects,
    /// The eye is inside the object of this line (every primary ray starts inside it).
    EyeInsideObject { object: u32 },
    /// The point light of line `light` is inside the opaque object of line `object`: it lights
    /// nothing outside it.
    LightInsideObject { light: u32, object: u32 },
}

impl fmt::Display for SceneWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoLight => f.write_str("no `light` statement: the default light is used"),
            Self::NoObjects => f.write_str("no objects: the picture is the background alone"),
            Self::EyeInsideObject { object } => write!(f, "the eye is inside the object of line {object}: every ray starts inside it"),
            Self::LightInsideObject { light, object } => write!(f, "the light of line {light} is inside the opaque object of line {object}: it lights nothing outside it"),
        }
    }
}

/// Whether `point` (world space) is inside `object` (a closed primitive; an open surface or a
/// solid's box encloses nothing here).
fn inside(object: &ObjectDescription, point: [f64; 3]) -> bool {
    if matches!(object.primitive, Primitive::Solid(_)) {
        return false;
    }
    let Some(inverse) = object.world_from_object.affine_inverse() else { return false };
    let local = inverse.transform_point(point);
    crate::csg::leaf::contains::<f64>(object.primitive, Vector3::from_f64(local))
}

impl<L: Deref<Target = [ObjectDescription]>> Description<L> {
    /// What may make the picture other than meant ([`SceneWarning`]), each once, in the
    /// scene's order: `report` is called for each.
    pub fn warnings(&self, mut report: impl FnMut(SceneWarning)) {
        if self.objects.is_empty() {
            report(SceneWarning::NoObjects);
        }
        if self.lines.light == 0 {
            report(SceneWarning::NoLight);
        }
        if let Projection::Perspective { eye } = self.projection {
            if let Some(object) = self.objects.iter().find(|object| inside(object, eye)) {
                report(SceneWarning::EyeInsideObject { object: object.line });
            }
        }
        let first = core::iter::once((self.light, self.lines.light));
        for (light, line) in first.chain(self.more_lights.iter().map(|source| (source.light, source.line))) {
            let Light::Point(position) = light else { continue };
            if let Some(object) = self.objects.iter().find(|object| object.material.transmit == 0.0 && inside(object, position)) {
                report(SceneWarning::LightInsideObject { light: line, object: object.line });
            }
        }
    }
}
