//! The render-ready scene in a chosen number type: each object's inverse transform and
//! material, the camera, the light, and the shading constants. Everything that can be done once
//! per scene is done here (the thesis's `preprocess`, §4.7 and RTRACE.C), so the per-pixel code
//! only reads.
//!
//! Storage is fixed at compile time: `MAX_OBJECTS` objects, no allocator.

use heapless::Vec;

use crate::camera::Camera;
use crate::geometry::{AffineTransform, Vector3};
use crate::number::Number;
use crate::optimize::Acceleration;
use crate::parser::{SceneError, SceneErrorKind};
use crate::scene::range::{self, RayOrigins};
use crate::scene::{Light, ObjectDescription, Optimizations, Primitive, SceneDescription, Viewport};
use crate::shading::{Palette, ShadingConstants};

/// An object's surface constants in the number type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedMaterial<N> {
    pub colour: u8,
    pub ka: N,
    pub kd: N,
    pub ks: N,
    pub rnd: N,
    /// The specular exponent rounded to an integer.
    pub power: u32,
    /// RGB mode: the fraction of red, green and blue reflected, `1 − cmy`.
    pub reflectance: [N; 3],
}

/// One object as the tracer needs it: the primitive, world -> object, and the material.
/// The forward transform is not kept: only the inverse is used per ray, and normals go back
/// through its transpose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Object<N> {
    pub primitive: Primitive,
    pub object_from_world: AffineTransform<N>,
    pub material: PreparedMaterial<N>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PreparedLight<N> {
    Point(Vector3<N>),
    /// Unit vector toward the light.
    Direction(Vector3<N>),
}

#[derive(Debug, Clone)]
pub struct Scene<N, const MAX_OBJECTS: usize> {
    pub objects: Vec<Object<N>, MAX_OBJECTS>,
    pub camera: Camera<N>,
    pub light: PreparedLight<N>,
    pub constants: ShadingConstants<N>,
    pub background: u8,
    pub shadows: bool,
    pub dither: bool,
    pub optimizations: Optimizations,
    pub palette: Palette,
    /// What the optimizations derived from the objects' bounding volumes (§4.7).
    pub acceleration: Acceleration<N, MAX_OBJECTS>,
}

impl<N: Number, const MAX_OBJECTS: usize> Scene<N, MAX_OBJECTS> {
    pub fn prepare<const CAPACITY: usize>(description: &SceneDescription<CAPACITY>) -> Result<Self, SceneError> {
        Self::prepare_with_objects(description, &description.objects)
    }

    /// Prepares the scene's settings from `description` with the objects given separately (the
    /// firmware keeps its objects in flash and its settings in a constant).
    pub fn prepare_with_objects<const CAPACITY: usize>(
        description: &SceneDescription<CAPACITY>,
        descriptions: &[ObjectDescription],
    ) -> Result<Self, SceneError> {
        range::check_camera_and_light::<N, CAPACITY>(description)?;
        let origins = RayOrigins::of(description, descriptions);
        let mut objects = Vec::new();
        for object in descriptions {
            let error = |kind| SceneError { line: object.line, kind };
            if !object.primitive.is_compiled() {
                return Err(error(SceneErrorKind::PrimitiveNotCompiled { primitive: object.primitive.name() }));
            }
            let inverse = object.world_from_object.affine_inverse().ok_or(error(SceneErrorKind::SingularTransform))?;
            range::check_object::<N>(object, &inverse, &origins)?;
            let material = &object.material;
            let prepared = Object {
                primitive: object.primitive,
                object_from_world: AffineTransform::from_matrix(&inverse),
                material: PreparedMaterial {
                    colour: material.colour & 15,
                    ka: N::from_f64(material.ka),
                    kd: N::from_f64(material.kd),
                    ks: N::from_f64(material.ks),
                    rnd: N::from_f64(material.rnd),
                    power: libm::round(material.pwr.clamp(0.0, 1.0e6)) as u32,
                    reflectance: material.cmy.map(|c| N::from_f64((1.0 - c).clamp(0.0, 1.0))),
                },
            };
            objects.push(prepared).map_err(|_| error(SceneErrorKind::TooManyObjects { capacity: MAX_OBJECTS }))?;
        }
        let camera = Camera::new(description.viewport, description.window, description.view_plane, description.projection)
            .ok_or(SceneError { line: 0, kind: SceneErrorKind::ZeroDirection })?;
        let light = match description.light {
            Light::Point(position) => PreparedLight::Point(Vector3::from_f64(position)),
            Light::Direction(direction) => {
                let length = libm::sqrt(direction.iter().map(|c| c * c).sum::<f64>());
                if length == 0.0 || !length.is_finite() {
                    return Err(SceneError { line: 0, kind: SceneErrorKind::ZeroDirection });
                }
                PreparedLight::Direction(Vector3::from_f64(direction.map(|c| c / length)))
            }
        };
        let acceleration = Acceleration::build(&camera, description.optimizations, descriptions);
        Ok(Self {
            objects,
            camera,
            light,
            constants: ShadingConstants::new(description.ambient),
            background: description.background,
            shadows: description.shadows,
            dither: description.dither,
            optimizations: description.optimizations,
            palette: description.palette,
            acceleration,
        })
    }

    pub fn viewport(&self) -> Viewport {
        self.camera.viewport
    }

    /// The background in RGB mode: the look-up table's colour for the background index (the
    /// thesis wrote the index into the red byte only, digest §11 B7).
    pub fn background_rgb(&self) -> [u8; 3] {
        self.palette.entry(self.background).to_rgb888()
    }
}
