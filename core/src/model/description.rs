//! The scene as written: every global setting of the thesis's user interface (§2.1 of the
//! digest) and the list of objects, with the defaults of `docs/scene-format.md`.
//! The objects' list is a type parameter: a `heapless::Vec` of a capacity fixed at compile
//! time ([`SceneDescription`]) on the firmware, a list sized at run time on a host.

use core::ops::Deref;

use heapless::Vec;

use super::object_description::ObjectDescription;
use super::solid::{SolidNode, MAX_SOLID_NODES};
use super::{Light, LightSource, Optimizations, Palette, Projection, Viewport, Window, MAX_LIGHTS};

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

/// A whole scene as written, before any number type is chosen, its objects in `L`.
#[derive(Clone, Debug, PartialEq)]
pub struct Description<L> {
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
    pub objects: L,
    /// The operands and operations of every solid (`Primitive::Solid` names its range), in
    /// post-order (`model::solid`).
    pub solids: Vec<SolidNode, MAX_SOLID_NODES>,
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

/// A scene as written with room for `MAX_OBJECTS` objects (capacity in the type).
pub type SceneDescription<const MAX_OBJECTS: usize> = Description<Vec<ObjectDescription, MAX_OBJECTS>>;

impl<L: Deref<Target = [ObjectDescription]>> Description<L> {
    /// Every primitive the scene intersects, with its line: its objects' and its solids'
    /// operands' (a solid is not one; [`Description::solids`] says whether it has any).
    pub fn primitives(&self) -> impl Iterator<Item = (super::Primitive, u32)> + '_ {
        let objects = self.objects.iter().filter(|object| !matches!(object.primitive, super::Primitive::Solid(_))).map(|object| (object.primitive, object.line));
        let operands = self.solids.iter().filter_map(|node| match node {
            SolidNode::Leaf(leaf) => Some((leaf.primitive, leaf.line)),
            SolidNode::Combine { .. } => None,
        });
        objects.chain(operands)
    }

    /// Whether the scene uses anything of chapter 5 (reflection, refraction, a second light or
    /// an intensity, antialiasing): without, it renders exactly as the thesis's pipeline.
    pub fn uses_chapter_five(&self) -> bool {
        self.light_intensity != 1.0 || !self.more_lights.is_empty() || self.antialias.is_some() || self.objects.iter().any(|object| object.material.spawns_rays())
    }
}

impl<L: Default> Default for Description<L> {
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
            objects: L::default(),
            solids: Vec::new(),
            lines: SettingLines::default(),
        }
    }
}
