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
use crate::optimize::{Acceleration, Tuning};
use crate::parser::{SceneError, SceneErrorKind};
use crate::scene::range::{self, RayOrigins};
use crate::scene::{Light, ObjectDescription, Optimizations, Primitive, SceneDescription, Viewport};
use crate::shading::{Palette, Rgb4, ShadingConstants};

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
    /// A perspective view's eye in object space (`object_from_world.point(eye)`, the same
    /// bits as transforming it per ray): every primary ray starts there, so a ray–object test
    /// transforms only the direction. Zero for a parallel view.
    pub eye: Vector3<N>,
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
        let mut scene = Self::UNPREPARED;
        scene.prepare_in_place(description, descriptions)?;
        Ok(scene)
    }

    /// Every byte zero, no objects: the value of a scene to be prepared in place. The firmware
    /// keeps its scene in a `static` of this value (zero-initialised RAM, no flash) and
    /// prepares it there: a scene returned by value would pass through the stack.
    pub const UNPREPARED: Self = Self {
        objects: Vec::new(),
        camera: Camera::UNSET,
        light: PreparedLight::Point(Vector3 { x: N::ZERO, y: N::ZERO, z: N::ZERO }),
        constants: ShadingConstants {
            fifteen: N::ZERO,
            brightest: N::ZERO,
            half: N::ZERO,
            noise_step: N::ZERO,
            ambient: N::ZERO,
            full_rgb: N::ZERO,
            brightest_rgb: N::ZERO,
        },
        background: 0,
        shadows: false,
        dither: false,
        optimizations: Optimizations::NONE,
        palette: Palette { entries: [Rgb4 { r: 0, g: 0, b: 0 }; 256] },
        acceleration: Acceleration::UNSET,
    };

    /// [`Scene::prepare_with_objects`] into `self`, every part written in place (any earlier
    /// scene is replaced).
    pub fn prepare_in_place<const CAPACITY: usize>(
        &mut self,
        description: &SceneDescription<CAPACITY>,
        descriptions: &[ObjectDescription],
    ) -> Result<(), SceneError> {
        let (camera, light) = Self::camera_and_light(description)?;
        self.camera = camera;
        self.light = light;
        self.constants = ShadingConstants::new(description.ambient);
        self.background = description.background;
        self.shadows = description.shadows;
        self.dither = description.dither;
        self.optimizations = description.optimizations;
        self.palette = description.palette;
        self.prepare_objects(description, descriptions)
    }

    fn camera_and_light<const CAPACITY: usize>(
        description: &SceneDescription<CAPACITY>,
    ) -> Result<(Camera<N>, PreparedLight<N>), SceneError> {
        let camera = Camera::new(description.viewport, description.window, description.view_plane, description.projection)
            .ok_or(SceneError { line: description.lines.projection, kind: SceneErrorKind::ZeroDirection })?;
        let light = match description.light {
            Light::Point(position) => PreparedLight::Point(Vector3::from_f64(position)),
            Light::Direction(direction) => {
                let length = libm::sqrt(direction.iter().map(|c| c * c).sum::<f64>());
                if length == 0.0 || !length.is_finite() {
                    return Err(SceneError { line: description.lines.light, kind: SceneErrorKind::ZeroDirection });
                }
                PreparedLight::Direction(Vector3::from_f64(direction.map(|c| c / length)))
            }
        };
        Ok((camera, light))
    }

    /// Prepares the objects into `self.objects` and builds the acceleration structures, in place.
    fn prepare_objects<const CAPACITY: usize>(
        &mut self,
        description: &SceneDescription<CAPACITY>,
        descriptions: &[ObjectDescription],
    ) -> Result<(), SceneError> {
        range::check_camera_and_light::<N, CAPACITY>(description)?;
        let origins = RayOrigins::of(description, descriptions);
        let objects = &mut self.objects;
        objects.clear();
        for object in descriptions {
            let error = |kind| SceneError { line: object.line, kind };
            if !object.primitive.is_compiled() {
                return Err(error(SceneErrorKind::PrimitiveNotCompiled { primitive: object.primitive.name() }));
            }
            let inverse = object.world_from_object.affine_inverse().ok_or(error(SceneErrorKind::SingularTransform))?;
            range::check_object::<N>(object, &inverse, &origins)?;
            let material = &object.material;
            let object_from_world = AffineTransform::from_matrix(&inverse);
            let prepared = Object {
                primitive: object.primitive,
                object_from_world,
                eye: self.camera.eye().map_or(Vector3::zero(), |eye| object_from_world.point(eye)),
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
        self.acceleration.rebuild(&self.camera, description.optimizations, descriptions, Tuning::IMPROVED);
        Ok(())
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
