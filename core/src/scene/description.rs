//! The scene as written: every global setting of the thesis's user interface (§2.1 of the
//! digest) and the list of objects, with the defaults of `docs/scene-format.md`.
//! Capacities are in the type: `MAX_OBJECTS` is how many objects the build can hold.

use heapless::Vec;

use crate::geometry::Matrix4;
use crate::shading::Palette;

/// The four unit primitives of §4.2.5 (fig 4.6), in the thesis's enum order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Primitive {
    /// The unit cube `[0,1]^3`.
    Cube,
    /// The unit sphere at the origin.
    Sphere,
    /// Radius 1 about +z, from z = 0 to z = 1, both caps.
    Cylinder,
    /// Apex at the origin, base of radius 1 at z = 1, capped.
    Cone,
}

impl Primitive {
    pub const ALL: [Primitive; 4] = [Primitive::Cube, Primitive::Sphere, Primitive::Cylinder, Primitive::Cone];

    /// The keyword (the thesis's `nameof` table).
    pub const fn name(self) -> &'static str {
        match self {
            Primitive::Cube => "cube",
            Primitive::Sphere => "sphere",
            Primitive::Cylinder => "cylinder",
            Primitive::Cone => "cone",
        }
    }
}

/// The screen rectangle in pixels, inclusive (`setviewport`). y grows upward, as on the PGA.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub x1: u16,
    pub x2: u16,
    pub y1: u16,
    pub y2: u16,
}

impl Viewport {
    pub const fn width(&self) -> u16 {
        self.x2 - self.x1 + 1
    }
    pub const fn height(&self) -> u16 {
        self.y2 - self.y1 + 1
    }
    pub const fn pixel_count(&self) -> u32 {
        self.width() as u32 * self.height() as u32
    }
}

/// The rectangle on the view plane that the viewport maps onto (`setwindow`); `x1 < x2`,
/// `y1 < y2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    pub x1: f64,
    pub x2: f64,
    pub y1: f64,
    pub y2: f64,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Rays start on the view plane and travel along `direction` (never zero).
    Parallel { direction: [f64; 3] },
    /// Rays start at `eye` and pass through the view plane.
    Perspective { eye: [f64; 3] },
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light {
    /// A point light at this position.
    Point([f64; 3]),
    /// A directional light; the vector points toward the light (never zero).
    Direction([f64; 3]),
}

/// Which of the four optimizations of §4.7 are on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Optimizations {
    pub pixelbuffer: bool,
    pub extents: bool,
    pub grid: bool,
    pub sortlist: bool,
}

impl Optimizations {
    pub const ALL: Self = Self { pixelbuffer: true, extents: true, grid: true, sortlist: true };
    pub const NONE: Self = Self { pixelbuffer: false, extents: false, grid: false, sortlist: false };

    /// `all`, `none`, or a comma-separated list of `pixelbuffer`, `extents`, `grid` and
    /// `sortlist` (the command line's `--opt` and the firmware build's `MICROTRACE_OPT`);
    /// `Err` holds the first unknown name.
    pub fn from_list(text: &str) -> Result<Self, &str> {
        match text {
            "all" => return Ok(Self::ALL),
            "none" => return Ok(Self::NONE),
            _ => {}
        }
        let mut chosen = Self::NONE;
        for word in text.split(',') {
            match word.trim() {
                "pixelbuffer" => chosen.pixelbuffer = true,
                "extents" => chosen.extents = true,
                "grid" => chosen.grid = true,
                "sortlist" => chosen.sortlist = true,
                other => return Err(other),
            }
        }
        Ok(chosen)
    }

    /// All 16 combinations, `NONE` first.
    pub fn combinations() -> impl Iterator<Item = Self> {
        (0u8..16).map(|bits| Self {
            pixelbuffer: bits & 1 != 0,
            extents: bits & 2 != 0,
            grid: bits & 4 != 0,
            sortlist: bits & 8 != 0,
        })
    }
}

/// Surface constants of one object (table 4.1), defaults from `getobject`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Colour group 0..15 (`clr`).
    pub colour: u8,
    pub ka: f64,
    pub kd: f64,
    pub ks: f64,
    /// Specular exponent.
    pub pwr: f64,
    /// Roughness: noise of up to `rnd` shade steps.
    pub rnd: f64,
    /// Cyan, magenta, yellow reflection ratios (RGB mode).
    pub cmy: [f64; 3],
    /// Reflection coefficient kr, 0..1 (chapter 5, `reflect`): the share of the reflected ray's
    /// colour added to the local shade.
    pub reflect: f64,
    /// Transmission coefficient kt, 0..1 (`transmit`): the share of the refracted ray's colour,
    /// and the share of a light that a shadow ray through the object passes.
    pub transmit: f64,
    /// Refractive index of the inside (`ior`), 0.1..10.
    pub ior: f64,
}

impl Default for Material {
    fn default() -> Self {
        Self { colour: 0, ka: 1.0, kd: 0.4, ks: 0.6, pwr: 20.0, rnd: 0.8, cmy: [0.3; 3], reflect: 0.0, transmit: 0.0, ior: 1.0 }
    }
}

impl Material {
    /// Whether rays leave this surface for more than the light (a mirror or a glass).
    pub fn spawns_rays(&self) -> bool {
        self.reflect > 0.0 || self.transmit > 0.0
    }
}

/// How many lights a scene may have (chapter 5: each `light` statement adds one).
pub const MAX_LIGHTS: usize = 4;

/// A light beyond the first, with its intensity and the line that set it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSource {
    pub light: Light,
    pub intensity: f64,
    pub line: u32,
}

/// Adaptive antialiasing (thesis fig 2.9): split a pixel whose corners differ by more than
/// `threshold` (a fraction of full scale), down to `levels` splits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Antialias {
    pub threshold: f64,
    pub levels: u8,
}

/// The ray tree's default depth (`depth`, scene format): primary rays and four generations.
pub const DEFAULT_DEPTH: u8 = 5;
/// The deepest tree the format allows.
pub const MAX_DEPTH: u8 = 8;

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

/// A whole scene as written, before any number type is chosen.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneDescription<const MAX_OBJECTS: usize> {
    pub viewport: Viewport,
    pub window: Window,
    /// The view plane is z = `view_plane`.
    pub view_plane: f64,
    pub projection: Projection,
    /// The first light (the thesis's only one).
    pub light: Light,
    /// The first light's intensity (1 unless written).
    pub light_intensity: f64,
    /// Every further `light` statement's light, in order (chapter 5).
    pub more_lights: Vec<LightSource, { MAX_LIGHTS - 1 }>,
    /// The ray tree's maximum depth, 1..=[`MAX_DEPTH`]: 1 traces primary rays only.
    pub depth: u8,
    /// Adaptive antialiasing, when on.
    pub antialias: Option<Antialias>,
    /// Ambient intensity Ia.
    pub ambient: f64,
    /// Background palette index.
    pub background: u8,
    pub shadows: bool,
    pub dither: bool,
    pub optimizations: Optimizations,
    /// The 256-entry look-up table built from the `group` statements.
    pub palette: Palette,
    pub objects: Vec<ObjectDescription, MAX_OBJECTS>,
    /// Where the camera and light settings were written, for errors that scene preparation
    /// finds in them (0: the format's default, not written).
    pub lines: SettingLines,
}

/// The line of the last `window`, `viewplane` and projection (`perspective` / `parallel`)
/// statement of a scene and of its first `light` statement, 0 where the default holds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SettingLines {
    pub window: u32,
    pub view_plane: u32,
    pub projection: u32,
    pub light: u32,
    pub antialias: u32,
}

impl<const MAX_OBJECTS: usize> SceneDescription<MAX_OBJECTS> {
    /// Whether the scene uses anything of chapter 5 (reflection, refraction, a second light or
    /// an intensity, antialiasing): without, it renders exactly as the thesis's pipeline.
    pub fn uses_chapter_five(&self) -> bool {
        self.light_intensity != 1.0 || !self.more_lights.is_empty() || self.antialias.is_some() || self.objects.iter().any(|object| object.material.spawns_rays())
    }
}

impl<const MAX_OBJECTS: usize> Default for SceneDescription<MAX_OBJECTS> {
    /// The defaults of the scene format (the thesis's compiled defaults, with `optimize all`).
    fn default() -> Self {
        Self {
            viewport: Viewport { x1: 0, x2: 639, y1: 0, y2: 479 },
            window: Window { x1: -100.0, x2: 100.0, y1: -100.0, y2: 100.0 },
            view_plane: 500.0,
            projection: Projection::Parallel { direction: [0.0, 0.0, -1.0] },
            light: Light::Direction([1.0, 1.0, 1.0]),
            light_intensity: 1.0,
            more_lights: Vec::new(),
            depth: DEFAULT_DEPTH,
            antialias: None,
            ambient: 0.2,
            background: 113,
            shadows: false,
            dither: false,
            optimizations: Optimizations::ALL,
            palette: Palette::grey(),
            objects: Vec::new(),
            lines: SettingLines::default(),
        }
    }
}
