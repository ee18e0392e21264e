//! The render-ready scene in a chosen number type: each object's inverse transform and
//! material, the camera, the light, and the shading constants. Everything that can be done once
//! per scene is done here (the thesis's `preprocess`, §4.7 and RTRACE.C), so the per-pixel code
//! only reads.
//!
//! Storage is the build's [`Config`]'s: with [`Arrays`], fixed at compile time; no allocator.

use core::ops::Deref;

use crate::model::{Object, PreparedMaterial};

use crate::camera::Camera;
use crate::config::{Arrays, Config, PaletteStorage};
use crate::storage::{List, Table, Unset};
use crate::geometry::{AffineTransform, Vector3};
use crate::light::{PreparedLight, PreparedLightSource};
use crate::number::Number;
#[cfg(feature = "ray-tree")]
use crate::optimize::bounding_sphere::BoundingSphere;
#[cfg(feature = "ray-tree")]
use crate::optimize::space_grid::SpaceGrid;
use crate::optimize::{Acceleration, Tuning};
use crate::model::{SceneError, SceneErrorKind};
use crate::scene::range::{self, RayOrigins};
use crate::model::{Antialias, Description, ObjectDescription, Optimizations, Viewport, Window};
use crate::shading::ShadingConstants;
use crate::model::PreparedSolidNode;
#[cfg(feature = "csg")]
use crate::model::{Extent, MAX_SOLID_NODES, NO_SKIP};
#[cfg(feature = "csg")]
use crate::optimize::{capsule::ScreenMap, ObjectBounds};

/// Adaptive antialiasing as the render needs it (thesis fig 2.9): the image's viewport, the
/// subdivision levels L and the threshold on an 8-bit channel's range over a square's corners.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PreparedAntialias {
    pub image: Viewport,
    pub levels: u8,
    pub threshold: u8,
}

impl PreparedAntialias {
    /// `None` when the sample grid would not fit in `u16` coordinates below 32767.
    pub fn new(antialias: Antialias, image: Viewport) -> Option<Self> {
        let step = 1u32 << antialias.levels;
        let fits = |pixels: u16| u32::from(pixels) * step < 32767;
        (fits(image.width()) && fits(image.height()) && antialias.levels <= 4).then_some(Self {
            image,
            levels: antialias.levels,
            threshold: libm::round(antialias.threshold.clamp(0.0, 1.0) * 255.0) as u8,
        })
    }

    /// Samples per pixel side, 2^L.
    pub fn step(&self) -> u16 {
        1 << self.levels
    }

    /// The sample grid's viewport and window: (W·2^L + 1) x (H·2^L + 1) samples, from half a
    /// pixel before the first pixel's sample to half a pixel after the last (the pixels'
    /// corners; a single column or row spans the window).
    pub fn sample_grid(&self, image: Viewport, window: Window) -> (Viewport, Window) {
        let step = self.step();
        let viewport = Viewport { x1: 0, x2: image.width() * step, y1: 0, y2: image.height() * step };
        // Half the spacing of the pixels' samples; a single column or row covers the window.
        let half = |from: f64, to: f64, pixels: u16| if pixels > 1 { (to - from) / f64::from(pixels - 1) / 2.0 } else { 0.0 };
        let (hx, hy) = (half(window.x1, window.x2, image.width()), half(window.y1, window.y2, image.height()));
        (viewport, Window { x1: window.x1 - hx, x2: window.x2 + hx, y1: window.y1 - hy, y2: window.y2 + hy })
    }
}

/// What an object does with the rays of the ray tree (chapter 5): the share it reflects, the
/// share it transmits, and the refractive index of its inside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Optics<N> {
    pub reflect: N,
    pub transmit: N,
    pub ior: N,
}

/// A scene prepared with the tables its build's [`Config`] gives it (arrays sized at compile
/// time in [`Arrays`], the firmware's and the tests'; storage sized at run time on a host).
pub type Scene<N, const MAX_OBJECTS: usize> = Prepared<Arrays<N, MAX_OBJECTS>>;

/// The render-ready scene (see the module's comment), its tables the build's `C`.
pub struct Prepared<C: Config> {
    pub objects: C::Objects,
    /// A perspective view's eye in each object's space (`object_from_world.point(eye)`, the
    /// same bits as transforming it per ray), indexed like `objects`: every primary ray starts
    /// there, so a ray–object test transforms only the direction. Zero for a parallel view.
    /// It depends on the view, so it is kept apart from the objects (which may be in flash);
    /// baked with the view's other tables where they are (read through [`Prepared::eyes`]).
    pub eyes: C::ViewTable<Vector3<C::Number>>,
    pub camera: Camera<C::Number>,
    /// The first light (the thesis's only one).
    pub light: PreparedLight<C::Number>,
    /// The first light's intensity; exactly one unless the scene wrote another, and then the
    /// shading multiplies by it.
    pub light_intensity: C::Number,
    /// The lights of later `light` statements (chapter 5).
    pub more_lights: C::OtherLights<PreparedLightSource<C::Number>>,
    /// The ray tree (chapter 5): the objects' optics, indexed like `objects`, empty when no
    /// object reflects or transmits; and the tree's depth (1: primary rays only).
    #[cfg(feature = "ray-tree")]
    pub optics: C::PerObjectList<Optics<C::Number>>,
    /// Whether some object's `transmit` is above zero: found once at preparation, asked by
    /// every shadow ray ([`Scene::has_transparent_objects`]).
    #[cfg(feature = "ray-tree")]
    pub transparent: bool,
    /// The objects' world-space spheres for secondary rays, filled with `optics`.
    #[cfg(feature = "ray-tree")]
    pub spheres: C::PerObjectList<BoundingSphere<C::Number>>,
    /// The uniform 3-D grid over the spheres for secondary rays (none without spheres).
    #[cfg(feature = "ray-tree")]
    pub space_grid: SpaceGrid<C>,
    pub depth: u8,
    /// Adaptive antialiasing (chapter 5, fig 2.9), when on: the camera is then the sample grid.
    pub antialias: Option<PreparedAntialias>,
    pub constants: ShadingConstants<C::Number>,
    pub background: u8,
    pub shadows: bool,
    pub dither: bool,
    pub optimizations: Optimizations,
    /// The look-up table (`Config::Palette`: in flash on the firmware).
    pub palette: C::Palette,
    /// What the optimizations derived from the objects' bounding volumes (§4.7).
    pub acceleration: Acceleration<C>,
    /// Every solid's nodes, prepared (`csg::solid`): a solid object's `Primitive::Solid` range
    /// indexes it as it indexes the description's.
    #[cfg(feature = "csg")]
    pub solid_nodes: C::Solids,
}

impl<C: Config> core::fmt::Debug for Prepared<C> {
    fn fmt(&self, formatter: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        formatter.debug_struct("Prepared").field("objects", &self.objects.len()).field("camera", &self.camera).field("depth", &self.depth).field("optimizations", &self.optimizations).finish_non_exhaustive()
    }
}

impl<C: Config> Prepared<C> {
    /// Every byte zero (a baked scene's objects, in flash, take none): the value of a scene to
    /// be prepared in place. A board keeps its scene in a `static` of this value
    /// (zero-initialised RAM, no flash) and prepares it there: a scene returned by value would
    /// pass through the stack.
    pub const UNPREPARED: Self = Self {
        objects: Unset::UNSET,
        eyes: Unset::UNSET,
        camera: Camera::UNSET,
        light: PreparedLight::Point(Vector3::UNSET),
        light_intensity: Unset::UNSET,
        more_lights: Unset::UNSET,
        #[cfg(feature = "ray-tree")]
        optics: Unset::UNSET,
        #[cfg(feature = "ray-tree")]
        transparent: false,
        #[cfg(feature = "ray-tree")]
        spheres: Unset::UNSET,
        #[cfg(feature = "ray-tree")]
        space_grid: SpaceGrid::NONE,
        depth: 0,
        antialias: None,
        constants: ShadingConstants::UNSET,
        background: 0,
        shadows: false,
        dither: false,
        optimizations: Optimizations::NONE,
        palette: Unset::UNSET,
        acceleration: Acceleration::UNSET,
        #[cfg(feature = "csg")]
        solid_nodes: Unset::UNSET,
    };
}

impl<N: Number, C: Config<Number = N>> Prepared<C> {
    /// Nothing prepared, `objects` kept, every table made for `count` objects (an array has its
    /// own length whatever `count`): the start of a scene whose storage is sized at run time.
    pub fn for_objects(objects: C::Objects, count: usize) -> Self {
        Self {
            objects,
            eyes: C::ViewTable::filled(count, Vector3::zero()),
            camera: Camera::UNSET,
            light: PreparedLight::Point(Vector3::zero()),
            light_intensity: N::ZERO,
            more_lights: Default::default(),
            #[cfg(feature = "ray-tree")]
            optics: C::PerObjectList::default(),
            #[cfg(feature = "ray-tree")]
            transparent: false,
            #[cfg(feature = "ray-tree")]
            spheres: C::PerObjectList::default(),
            #[cfg(feature = "ray-tree")]
            space_grid: SpaceGrid::none(count),
            depth: 0,
            antialias: None,
            constants: ShadingConstants { fifteen: N::ZERO, brightest: N::ZERO, half: N::ZERO, noise_step: N::ZERO, ambient: N::ZERO, full_rgb: N::ZERO, brightest_rgb: N::ZERO },
            background: 0,
            shadows: false,
            dither: false,
            optimizations: Optimizations::NONE,
            palette: C::Palette::default(),
            acceleration: Acceleration::unset(count),
            #[cfg(feature = "csg")]
            solid_nodes: C::Solids::default(),
        }
    }
}

/// Preparation from a description, for a scene that owns its objects (a list it can fill).
impl<N: Number, C: Config<Number = N>> Prepared<C>
where
    C::Objects: List<Object<N>>,
    C::Solids: List<PreparedSolidNode<N>>,
{
    /// The scene `description` describes, its tables sized for its objects (or the `Config`'s
    /// arrays).
    pub fn prepare<L: Deref<Target = [ObjectDescription]>>(description: &Description<L>) -> Result<Self, SceneError> {
        Self::prepare_with_objects(description, &description.objects)
    }

    /// Prepares the scene's settings from `description` with the objects given separately.
    pub fn prepare_with_objects<L: Deref<Target = [ObjectDescription]>>(description: &Description<L>, descriptions: &[ObjectDescription]) -> Result<Self, SceneError> {
        let mut scene = Self::for_objects(C::Objects::default(), descriptions.len());
        scene.prepare_in_place(description, descriptions)?;
        Ok(scene)
    }

    /// [`Scene::prepare_with_objects`] into `self`, every part written in place (any earlier
    /// scene is replaced).
    pub fn prepare_in_place<L: Deref<Target = [ObjectDescription]>>(
        &mut self,
        description: &Description<L>,
        descriptions: &[ObjectDescription],
    ) -> Result<(), SceneError> {
        // A description built in code is held to the format's ranges, as a parsed one is.
        description.validate()?;
        for object in descriptions {
            object.validate()?;
        }
        #[cfg(not(feature = "antialias"))]
        if description.antialias.is_some() {
            return Err(SceneError { line: description.lines.antialias, kind: SceneErrorKind::FeatureNotCompiled { feature: "antialias", statement: "antialias" } });
        }
        let (camera, light) = Self::camera_and_light(description, description.antialias)?;
        self.camera = camera;
        self.light = light;
        self.light_intensity = N::from_f64(description.light_intensity);
        self.more_lights.clear();
        for source in &description.more_lights {
            let light = PreparedLight::new(source.light, source.line)?;
            let capacity = <C::OtherLights<PreparedLightSource<N>> as List<_>>::CAPACITY.saturating_add(1);
            self.more_lights
                .push(PreparedLightSource { light, intensity: N::from_f64(source.intensity) })
                .map_err(|_| SceneError { line: source.line, kind: SceneErrorKind::TooManyLights { capacity } })?;
        }
        self.depth = description.depth;
        self.antialias = match description.antialias {
            Some(antialias) => Some(PreparedAntialias::new(antialias, description.viewport).ok_or(SceneError {
                line: description.lines.antialias,
                kind: SceneErrorKind::InvalidRectangle { what: "antialias", requirement: "the viewport's width and height times 2^L must stay below 32767 samples" },
            })?),
            None => None,
        };
        self.constants = ShadingConstants::new(description.ambient);
        self.background = description.background;
        self.shadows = description.shadows;
        self.dither = description.dither;
        self.optimizations = description.optimizations;
        self.palette.hold(&description.palette);
        self.prepare_objects(description, descriptions)
    }

    /// The camera, and the first light. With antialiasing the camera samples the pixels'
    /// corners and their subdivisions (`render::antialias`): a grid 2^L times finer, reaching half
    /// a pixel beyond the window's edge samples, whose every sample is a "pixel" to the
    /// optimizations.
    fn camera_and_light<L>(
        description: &Description<L>,
        antialias: Option<Antialias>,
    ) -> Result<(Camera<N>, PreparedLight<N>), SceneError> {
        let (viewport, window) = match antialias.and_then(|antialias| PreparedAntialias::new(antialias, description.viewport)) {
            Some(prepared) => prepared.sample_grid(description.viewport, description.window),
            None => (description.viewport, description.window),
        };
        let camera = Camera::new(viewport, window, description.view_plane, description.projection)
            .ok_or(SceneError { line: description.lines.projection, kind: SceneErrorKind::ZeroDirection })?;
        Ok((camera, PreparedLight::new(description.light, description.lines.light)?))
    }

    /// Prepares the objects into `self.objects` and builds the acceleration structures, in place.
    fn prepare_objects<L>(
        &mut self,
        description: &Description<L>,
        descriptions: &[ObjectDescription],
    ) -> Result<(), SceneError> {
        range::check_camera_and_light::<N, L>(description)?;
        let origins = RayOrigins::of(description, descriptions);
        let objects = &mut self.objects;
        objects.clear();
        #[cfg(feature = "ray-tree")]
        let spawns_rays = descriptions.iter().any(|object| object.material.spawns_rays());
        #[cfg(feature = "ray-tree")]
        self.optics.clear();
        #[cfg(feature = "ray-tree")]
        self.spheres.clear();
        for object in descriptions {
            let error = |kind| SceneError { line: object.line, kind };
            if !object.primitive.is_compiled() {
                return Err(error(SceneErrorKind::PrimitiveNotCompiled { primitive: object.primitive.name() }));
            }
            let material = &object.material;
            let prepared = prepare_object::<N>(object, &origins)?;
            objects.push(prepared).map_err(|_| error(SceneErrorKind::TooManyObjects { capacity: C::MAX_OBJECTS }))?;
            #[cfg(feature = "ray-tree")]
            if spawns_rays {
                self.optics
                    .push(Optics { reflect: N::from_f64(material.reflect), transmit: N::from_f64(material.transmit), ior: N::from_f64(material.ior) })
                    .map_err(|_| error(SceneErrorKind::TooManyObjects { capacity: C::MAX_OBJECTS }))?;
                self.spheres
                    .push(BoundingSphere::of(object.primitive, &object.world_from_object))
                    .map_err(|_| error(SceneErrorKind::TooManyObjects { capacity: C::MAX_OBJECTS }))?;
            }
            #[cfg(not(feature = "ray-tree"))]
            if material.spawns_rays() {
                let statement = if material.reflect > 0.0 { "reflect" } else { "transmit" };
                return Err(error(SceneErrorKind::FeatureNotCompiled { feature: "ray-tree", statement }));
            }
        }
        #[cfg(feature = "csg")]
        self.prepare_solids(description, descriptions, &origins)?;
        self.place_eyes();
        self.acceleration.rebuild(&self.camera, description.optimizations, descriptions, Tuning::IMPROVED);
        #[cfg(feature = "ray-tree")]
        {
            self.space_grid.build(&self.spheres);
            self.transparent = self.optics.iter().any(|optics| optics.transmit > N::ZERO);
        }
        Ok(())
    }
}

/// One object (or a solid's leaf) in the number type: its inverse transform, checked against
/// the type's range, and its material.
fn prepare_object<N: Number>(object: &ObjectDescription, origins: &RayOrigins) -> Result<Object<N>, SceneError> {
    let error = |kind| SceneError { line: object.line, kind };
    let inverse = object.world_from_object.affine_inverse().ok_or(error(SceneErrorKind::SingularTransform))?;
    range::check_object::<N>(object, &inverse, origins)?;
    let material = &object.material;
    Ok(Object {
        primitive: object.primitive,
        object_from_world: AffineTransform::from_matrix(&inverse),
        material: PreparedMaterial {
            colour: material.colour & 15,
            ka: N::from_f64(material.ka),
            kd: N::from_f64(material.kd),
            ks: N::from_f64(material.ks),
            rnd: N::from_f64(material.rnd),
            // No highlight (NFF's Ks 0): the exponent is never seen, so none is raised (the
            // SPD's tree asks 100,000 of every surface, a square per bit per light).
            power: if material.ks == 0.0 { 0 } else { libm::round(material.pwr.clamp(0.0, 1.0e6)) as u32 },
            reflectance: material.cmy.map(|c| N::from_f64((1.0 - c).clamp(0.0, 1.0))),
        },
    })
}

#[cfg(feature = "csg")]
impl<N: Number, C: Config<Number = N>> Prepared<C>
where
    C::Solids: List<PreparedSolidNode<N>>,
{
    /// The solids' nodes in the number type, in the description's order, each solid's nodes
    /// linked (`csg::solid`) and their screen extents set for the view (§3.3.6).
    fn prepare_solids<L>(&mut self, description: &Description<L>, descriptions: &[ObjectDescription], origins: &RayOrigins) -> Result<(), SceneError> {
        self.solid_nodes.clear();
        for node in &description.solids {
            let prepared = match node {
                crate::model::SolidNode::Leaf(leaf) => {
                    if !leaf.primitive.is_compiled() {
                        return Err(SceneError { line: leaf.line, kind: SceneErrorKind::PrimitiveNotCompiled { primitive: leaf.primitive.name() } });
                    }
                    PreparedSolidNode::Leaf { object: prepare_object::<N>(leaf, origins)?, skip_to: NO_SKIP, top: 0, extent: Extent::EVERYWHERE }
                }
                crate::model::SolidNode::Combine { operation, .. } => PreparedSolidNode::Combine { operation: *operation, left: 0, extent: Extent::EVERYWHERE },
            };
            self.solid_nodes.push(prepared).map_err(|_| SceneError {
                line: 0,
                kind: SceneErrorKind::SolidTooComplex { what: "primitives and operations in the scene's solids", needs: description.solids.len(), capacity: MAX_SOLID_NODES },
            })?;
        }
        for object in descriptions {
            if let crate::model::Primitive::Solid(range) = object.primitive {
                let Some(nodes) = self.solid_nodes.get_mut(range.nodes()).and_then(|nodes| crate::csg::solid::link_nodes(nodes).map(|()| nodes)) else {
                    return Err(SceneError { line: object.line, kind: SceneErrorKind::SolidTooComplex { what: "nodes in one tree", needs: usize::from(range.count), capacity: MAX_SOLID_NODES } });
                };
                // The screen extents as the view sees them (§3.3.6), from each leaf's capsule.
                let leaves = description.solids.get(range.nodes()).unwrap_or(&[]);
                let capsule_of = |place: usize| match leaves.get(place) {
                    Some(crate::model::SolidNode::Leaf(leaf)) => ObjectBounds::<N>::of(leaf).map(|bounds| bounds.capsule),
                    _ => None,
                };
                crate::optimize::solid_extents::set_solid_extents(&ScreenMap::new(&self.camera), nodes, capsule_of);
            }
        }
        Ok(())
    }
}

#[cfg(feature = "csg")]
impl<N: Number, C: Config<Number = N>> Prepared<C> {
    /// The nodes of a solid object (empty for any other).
    #[inline]
    pub fn solid(&self, primitive: crate::model::Primitive) -> &[PreparedSolidNode<N>] {
        match primitive {
            crate::model::Primitive::Solid(range) => self.solid_nodes.get(range.nodes()).unwrap_or(&[]),
            _ => &[],
        }
    }
}

/// What the render reads of a prepared scene, wherever its objects live.
impl<N: Number, C: Config<Number = N>> Prepared<C> {
    /// Each object's eye ([`Scene::eyes`]) for the camera's view: per frame, as it depends on
    /// the view.
    pub(crate) fn place_eyes(&mut self) {
        let eye = self.camera.eye();
        for (slot, object) in self.eyes.slots_mut().iter_mut().zip(self.objects.iter()) {
            *slot = eye.map_or(Vector3::zero(), |eye| object.object_from_world.point(eye));
        }
    }

    /// Each object's eye in its own space: placed here, or baked with the view's tables.
    #[inline]
    pub fn eyes(&self) -> &[Vector3<N>] {
        self.eyes.slots()
    }

    /// All lights with their intensities, the first first.
    pub fn lights(&self) -> impl Iterator<Item = PreparedLightSource<N>> + '_ {
        core::iter::once(PreparedLightSource { light: self.light, intensity: self.light_intensity }).chain(self.more_lights.iter().copied())
    }

    /// Whether some object lets light through (so shadow rays measure a share, not a yes/no).
    #[cfg(feature = "ray-tree")]
    pub fn has_transparent_objects(&self) -> bool {
        self.transparent
    }

    /// The object's optics (none: a plain thesis surface).
    #[cfg(feature = "ray-tree")]
    pub fn optics(&self, index: usize) -> Optics<N> {
        self.optics.get(index).copied().unwrap_or(Optics { reflect: N::ZERO, transmit: N::ZERO, ior: N::ONE })
    }

    /// The object's sphere for secondary rays.
    #[cfg(feature = "ray-tree")]
    pub fn bounding_sphere(&self, index: usize) -> BoundingSphere<N> {
        self.spheres.get(index).copied().unwrap_or(BoundingSphere::EVERYWHERE)
    }

    /// The share of light the object passes (0 for an opaque one).
    #[cfg(feature = "ray-tree")]
    pub fn transmit(&self, index: usize) -> N {
        self.optics(index).transmit
    }

    /// Whether any object reflects or transmits (so pixels may need the ray tree).
    pub fn has_ray_tree(&self) -> bool {
        #[cfg(feature = "ray-tree")]
        return self.depth > 1 && !self.optics.is_empty();
        #[cfg(not(feature = "ray-tree"))]
        false
    }

    /// The image's viewport (with antialiasing the camera's is the finer sample grid's).
    pub fn viewport(&self) -> Viewport {
        match self.antialias {
            Some(antialias) => antialias.image,
            None => self.camera.viewport,
        }
    }

    /// The background in PGA mode: its palette index.
    pub fn background_index(&self) -> u8 {
        self.background
    }

    /// The background in RGB mode: the look-up table's colour for the background index (the
    /// thesis wrote the index into the red byte only, digest §11 B7).
    pub fn background_rgb(&self) -> [u8; 3] {
        self.palette.entry(self.background).to_rgb888()
    }
}
