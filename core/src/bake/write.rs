//! [`bake`]: a scene description to one self-contained Rust file (a host's, the `alloc`
//! feature): the number type, the scene's own `Config`, and every table as a `static`, every
//! number bit for bit ([`Number::write_literal`]). Nothing in the file depends on the features
//! of the crate that includes it: what the scene needs is decided here.

use alloc::boxed::Box;
use alloc::string::String;
use core::fmt::{self, Write};
use core::ops::Deref;

use crate::config::Config;
use crate::geometry::Vector3;
use crate::light::PreparedLight;
use crate::model::{solid_needs_and_box, Description, Extent, Object, ObjectDescription, Primitive, SceneError, SceneErrorKind, SolidNeeds};
use crate::number::{Number, NumberKind, SquareRoot};
use crate::optimize::bvh::Bvh;
use crate::optimize::grid::GridParts;
use crate::optimize::shadow_culling::{BlockerSet, DirectionChord, ShadowBound, ShadowTables};
use crate::optimize::AccelerationParts;
#[cfg(not(feature = "ray-tree"))]
use crate::optimize::bounding_sphere::BoundingSphere;
#[cfg(not(feature = "ray-tree"))]
use crate::scene::Optics;
use crate::scene::{Prepared, Scene};

/// The objects a baked scene may hold (its preparation on the host is an array of this many).
pub const BAKE_CAPACITY: usize = 512;

/// What to bake: the render's size, the number type, and what the target's core has.
#[derive(Clone, Copy, Debug)]
pub struct Bake<'a> {
    /// The render's width and height: the description is fitted to them
    /// ([`Description::fit_to_size`], as `microtrace render --size` does).
    pub size: (u16, u16),
    /// The number type the chip computes in.
    pub number: NumberKind,
    /// For a core with an FPU whose square root is an instruction: the path of the
    /// [`SquareRoot`] type that issues it, so that `f32` is `F32With<that>` (correctly
    /// rounded, as `f32`'s own: the same picture). `None`: the number type's own.
    pub f32_square_root: Option<&'a str>,
}

impl Bake<'static> {
    /// `width` x `height` in `number`, with the number type's own square root.
    pub const fn new(width: u16, height: u16, number: NumberKind) -> Self {
        Self { size: (width, height), number, f32_square_root: None }
    }
}

/// The host's stand-in for an FPU's correctly rounded square root: the scene baked in it is
/// bit for bit the one the chip would prepare.
struct CorrectlyRounded;

impl SquareRoot for CorrectlyRounded {
    const NAME: &'static str = "f32";

    fn sqrt(x: f32) -> f32 {
        libm::sqrtf(x)
    }
}

/// Bakes `description` at `bake.size` in `bake.number`: the Rust source of one file that a board
/// includes (`include!`) and prepares with [`Prepared::prepare_baked`]. It defines `Number`,
/// `SceneConfig` (the scene's own [`Config`]: its objects, solids and look-up table in flash,
/// every table sized by the scene), `SCENE` (a [`super::BakedScene`]) and the scene's
/// figures (`WIDTH`, `HEIGHT`, `PIXEL_COUNT`, `OBJECT_COUNT`, `OTHER_LIGHTS`, `NUMBER_NAME`).
/// The errors are the preparation's (a scene the number type cannot draw), without a line
/// where none applies; more than [`BAKE_CAPACITY`] objects is `TooManyObjects`.
pub fn bake<L: Deref<Target = [ObjectDescription]> + Clone>(description: &Description<L>, bake: &Bake<'_>) -> Result<String, SceneError> {
    let mut description = description.clone();
    description.fit_to_size(bake.size.0, bake.size.1);
    let square_root = bake.f32_square_root.filter(|_| bake.number == NumberKind::F32);
    let number_type = match square_root {
        Some(path) => alloc::format!("microtrace::number::F32With<{path}>"),
        None => String::from(bake.number.type_path()),
    };
    let mut out = String::new();
    match square_root {
        Some(_) => bake_in::<crate::number::F32With<CorrectlyRounded>, L>(&description, &number_type, bake.number, &mut out)?,
        None => crate::with_number_kind!(bake.number, N => bake_in::<N, L>(&description, &number_type, bake.number, &mut out))?,
    }
    Ok(out)
}

/// Prepares the scene on the host in `N` (as `microtrace render` does) and writes it.
fn bake_in<N: Number, L: Deref<Target = [ObjectDescription]>>(description: &Description<L>, number_type: &str, kind: NumberKind, out: &mut String) -> Result<(), SceneError> {
    if description.objects.len() > BAKE_CAPACITY {
        return Err(SceneError { line: 0, kind: SceneErrorKind::TooManyObjects { capacity: BAKE_CAPACITY } });
    }
    let mut scene = Box::new(Scene::<N, BAKE_CAPACITY>::UNPREPARED);
    scene.prepare_in_place(description, &description.objects)?;
    let objects = &description.objects[..];
    // A scene of many objects: the hierarchy of boxes a host builds (the chip has no f64 to
    // build one), used with Extents on, as on the host.
    let references = if cfg!(feature = "acceleration-tables") && scene.optimizations.extents { crate::optimize::hierarchy_references(objects.len()) } else { 0 };
    let mut nodes = alloc::vec![crate::optimize::bvh::BvhNode::<N>::UNSET; references];
    let mut order = alloc::vec![0u16; references];
    let hierarchy = baked_hierarchy(objects, &mut nodes, &mut order);
    // The grid the chip would build from the objects' bounds in the number type (no f64 there:
    // the eye-plane clip of objects reaching the eye is the host's only).
    let bounds: alloc::vec::Vec<crate::optimize::ObjectBounds<N>> = objects.iter().map(crate::optimize::ObjectBounds::or_everywhere).collect();
    let (camera, optimizations) = (scene.camera, scene.optimizations);
    scene.acceleration.rebuild_from_bounds(&camera, optimizations, &bounds);
    let figures = Figures::of(description);
    crate::render::built_shadow_tables(&*scene, |tables| {
        let mut parts = scene.acceleration.parts(tables);
        parts.hierarchy = hierarchy;
        parts.grid = parts.grid.filter(|_| optimizations.grid);
        // A `String` takes every write.
        write_file(&scene, &parts, &figures, number_type, kind, out).unwrap_or(());
    });
    Ok(())
}

/// The hierarchy of a baked scene of many objects, in `nodes` and `order` (as long as its
/// references; empty: none).
#[cfg(feature = "acceleration-tables")]
fn baked_hierarchy<'a, N: Number>(objects: &[ObjectDescription], nodes: &'a mut [crate::optimize::bvh::BvhNode<N>], order: &'a mut [u16]) -> Option<Bvh<'a, N, u16>> {
    if nodes.is_empty() {
        return None;
    }
    let references = nodes.len();
    let (mut boxes, mut triangles) = (alloc::vec![([0.0; 3], [0.0; 3]); objects.len()], alloc::vec![None; objects.len()]);
    let (mut pieces, mut owners) = (alloc::vec![([0.0; 3], [0.0; 3]); references], alloc::vec![0; references]);
    let scratch = crate::optimize::HierarchyScratch { boxes: &mut boxes, triangles: &mut triangles, references: &mut pieces, owners: &mut owners };
    crate::optimize::baked_hierarchy(objects, scratch, nodes, order)
}

#[cfg(not(feature = "acceleration-tables"))]
fn baked_hierarchy<'a, N: Number>(_objects: &[ObjectDescription], _nodes: &'a mut [crate::optimize::bvh::BvhNode<N>], _order: &'a mut [u16]) -> Option<Bvh<'a, N, u16>> {
    None
}

/// What sizes the scene's `Config`, from its description.
struct Figures {
    width: u16,
    height: u16,
    objects: usize,
    other_lights: usize,
    tree_depth: usize,
    corner_row: usize,
    spawns_rays: bool,
    solids: SolidNeeds,
}

impl Figures {
    fn of<L: Deref<Target = [ObjectDescription]>>(d: &Description<L>) -> Self {
        let spawns_rays = d.objects.iter().any(|object| object.material.spawns_rays());
        // A ray's walk through a solid holds lists of spans (`csg::solid`): exactly as many as
        // the scene's solids need, each need the largest over its solids (none without solids).
        let solids = d
            .objects
            .iter()
            .filter_map(|object| if let Primitive::Solid(range) = object.primitive { d.solids.get(range.nodes()) } else { None })
            .filter_map(|nodes| solid_needs_and_box(nodes).map(|(needs, _)| needs))
            .fold(SolidNeeds::default(), |all, one| SolidNeeds { spans: all.spans.max(one.spans), stack: all.stack.max(one.stack), held: all.held.max(one.held) });
        Self {
            width: d.viewport.width(),
            height: d.viewport.height(),
            objects: d.objects.len(),
            other_lights: d.more_lights.len(),
            // The ray tree's stack holds the scene's `depth`, or one (the primary hit) when no
            // object spawns rays.
            tree_depth: if spawns_rays { usize::from(d.depth) } else { 1 },
            // Antialiasing keeps one row of the pixels' corners: the image's width plus one.
            corner_row: if d.antialias.is_some() { usize::from(d.viewport.width()) + 1 } else { 1 },
            spawns_rays,
            solids,
        }
    }
}

/// Which of the tables a render may do without are baked.
#[derive(Clone, Copy)]
struct Baked {
    grid: bool,
    hierarchy: bool,
    shadow_tables: bool,
}

/// The storage of a table: in flash when baked, else none.
fn in_flash_or_none(baked: bool, element: &str) -> String {
    if baked {
        alloc::format!("microtrace::storage::InFlash<{element}>")
    } else {
        alloc::format!("[{element}; 0]")
    }
}

/// The whole file.
fn write_file<N: Number, C: Config<Number = N>>(scene: &Prepared<C>, parts: &AccelerationParts<'_, N, C::Index>, figures: &Figures, number_type: &str, kind: NumberKind, out: &mut dyn Write) -> fmt::Result
where
    C::Index: Into<u32>,
{
    write_figures(figures, number_type, kind, out)?;
    write_config(out, figures, Baked { grid: parts.grid.is_some(), hierarchy: parts.hierarchy.is_some(), shadow_tables: !parts.shadow_tables.is_empty() })?;
    write_objects(scene, out)?;
    write_grid(parts.grid, out)?;
    write_hierarchy(parts.hierarchy, out)?;
    write_shadow_tables(parts.shadow_tables, out)?;
    // Each object's eye (the host's table holds its capacity's).
    write_view(parts, scene.eyes().get(..scene.objects.len()).unwrap_or(&[]), out)?;
    write_scene(scene, parts, out)
}

/// The file's first lines: the number type and the scene's figures.
fn write_figures(figures: &Figures, number_type: &str, kind: NumberKind, out: &mut dyn Write) -> fmt::Result {
    let Figures { width, height, objects, other_lights, .. } = *figures;
    writeln!(out, "// Baked by microtrace::bake {}: do not edit.", env!("CARGO_PKG_VERSION"))?;
    writeln!(out, "/// The number type the tracer computes in.\npub type Number = {number_type};")?;
    // The figures are there to be read; a board reads those it needs.
    writeln!(out, "/// Its name (`microtrace render --number`).\n#[allow(dead_code)]\npub const NUMBER_NAME: &str = {:?};", kind.name())?;
    writeln!(out, "#[allow(dead_code)]\npub const WIDTH: u16 = {width};\n#[allow(dead_code)]\npub const HEIGHT: u16 = {height};\n#[allow(dead_code)]\npub const PIXEL_COUNT: usize = {};", usize::from(width) * usize::from(height))?;
    writeln!(out, "#[allow(dead_code)]\npub const OBJECT_COUNT: usize = {objects};\n/// The lights after the first.\n#[allow(dead_code)]\npub const OTHER_LIGHTS: usize = {other_lights};")
}

/// The file [`bake`] would write for `description`, with every table empty: the scene's
/// `SceneConfig` sized by its objects and what a bake would keep in flash (a grid with Grid on,
/// a hierarchy for more than [`BAKED_HIERARCHY_ABOVE`](crate::optimize::BAKED_HIERARCHY_ABOVE)
/// objects with Extents on), for a build that only measures what a scene of any size would
/// take (more objects than [`BAKE_CAPACITY`]: the firmware's report on Haines' SPD scenes).
/// `OBJECTS` and the other tables are empty, and there is no `SCENE`.
pub fn bake_sizes<L: Deref<Target = [ObjectDescription]> + Clone>(description: &Description<L>, bake: &Bake<'_>) -> String {
    let mut description = description.clone();
    description.fit_to_size(bake.size.0, bake.size.1);
    let figures = Figures::of(&description);
    let number_type = match bake.f32_square_root.filter(|_| bake.number == NumberKind::F32) {
        Some(path) => alloc::format!("microtrace::number::F32With<{path}>"),
        None => String::from(bake.number.type_path()),
    };
    let hierarchy = cfg!(feature = "acceleration-tables") && description.optimizations.extents && figures.objects > crate::optimize::BAKED_HIERARCHY_ABOVE;
    let mut out = String::new();
    let empty = "pub static OBJECTS: [microtrace::model::Object<Number>; 0] = [];\npub static SOLID_NODES: [microtrace::model::PreparedSolidNode<Number>; 0] = [];\npub static PALETTE: microtrace::model::Palette = microtrace::model::Palette { entries: [microtrace::model::Rgb4 { r: 0, g: 0, b: 0 }; 256] };";
    // A `String` takes every write.
    write_figures(&figures, &number_type, bake.number, &mut out)
        .and_then(|()| write_config(&mut out, &figures, Baked { grid: description.optimizations.grid, hierarchy, shadow_tables: false }))
        .and_then(|()| writeln!(out, "{empty}"))
        .unwrap_or(());
    out
}

/// `SceneConfig` and the storage of the objects, the solids and the look-up table, in flash.
fn write_config(out: &mut dyn Write, figures: &Figures, Baked { grid, hierarchy, shadow_tables }: Baked) -> fmt::Result {
    let Figures { objects, other_lights, tree_depth, corner_row, spawns_rays, solids, .. } = *figures;
    let per_object_list = if spawns_rays { objects } else { 0 };
    let space_entries = if spawns_rays { alloc::format!("[[u16; {}]; {objects}]", crate::config::SPACE_ENTRIES_PER_OBJECT) } else { String::from("[u16; 0]") };
    writeln!(
        out,
        r#"/// The scene's objects, prepared, in flash.
#[derive(Clone, Copy, Debug, Default)]
pub struct Objects;
impl core::ops::Deref for Objects {{
    type Target = [microtrace::model::Object<Number>];
    fn deref(&self) -> &Self::Target {{
        &OBJECTS
    }}
}}
impl microtrace::storage::Unset for Objects {{
    const UNSET: Self = Self;
}}
/// The solids' prepared nodes, in flash, and the lists a ray's walk through them holds.
#[derive(Clone, Copy, Debug, Default)]
pub struct Solids;
impl core::ops::Deref for Solids {{
    type Target = [microtrace::model::PreparedSolidNode<Number>];
    fn deref(&self) -> &Self::Target {{
        &SOLID_NODES
    }}
}}
impl microtrace::storage::Unset for Solids {{
    const UNSET: Self = Self;
}}
impl microtrace::config::SolidStorage<Number> for Solids {{
    type HeldSpans<T: Clone> = microtrace::storage::Capped<T, {held}>;
    type Spans<T: Clone> = microtrace::storage::Capped<T, {spans}>;
    type Lists<T: Clone> = microtrace::storage::Capped<T, {stack}>;
}}
/// The look-up table, in flash (768 bytes out of RAM).
#[derive(Clone, Copy, Debug, Default)]
pub struct Palette;
impl core::ops::Deref for Palette {{
    type Target = microtrace::model::Palette;
    fn deref(&self) -> &Self::Target {{
        &PALETTE
    }}
}}
impl microtrace::storage::Unset for Palette {{
    const UNSET: Self = Self;
}}
/// Baked from the same scene: it holds what preparation would give it.
impl microtrace::config::PaletteStorage for Palette {{
    fn hold(&mut self, _palette: &microtrace::model::Palette) {{}}
}}
/// The scene's own `Config`: its tables in flash, what it keeps in RAM sized by it.
#[derive(Debug)]
pub struct SceneConfig;
impl microtrace::config::Config for SceneConfig {{
    type Number = Number;
    type Index = u16;
    type Objects = Objects;
    type Solids = Solids;
    type Palette = Palette;
    type PerObject<T: Copy> = [T; {objects}];
    type ViewTable<T: Copy + microtrace::storage::Unset + 'static> = microtrace::storage::InFlash<T>;
    type PerObjectPerOtherLight<T: Copy> = [[T; {objects}]; {other_lights}];
    type OtherLights<T: Clone> = microtrace::storage::Capped<T, {other_lights}>;
    type PerObjectList<T: Clone> = microtrace::storage::Capped<T, {per_object_list}>;
    type GridPool<T: Copy + microtrace::storage::Unset + 'static> = {grid_pool};
    type SpaceEntries = {space_entries};
    type BlockerLists = [u16; 0];
    type Hierarchy<T: Copy + microtrace::storage::Unset + 'static> = {hierarchy_storage};
    type ScreenCells<T: Copy + microtrace::storage::Unset + 'static> = {grid_pool};
    type LightTables<T: Copy + microtrace::storage::Unset + 'static> = {shadow_storage};
    type TreeStack<T: Clone> = microtrace::storage::Capped<T, {tree_depth}>;
    type CornerRow = [[u8; 3]; {corner_row}];
    const MAX_OBJECTS: usize = {objects};
    const GRID_ENTRIES_PER_OBJECT: usize = 0;
    const TREE_DEPTH: usize = {tree_depth};
}}"#,
        held = solids.held,
        spans = solids.spans,
        stack = solids.stack,
        grid_pool = in_flash_or_none(grid, "T"),
        hierarchy_storage = in_flash_or_none(hierarchy, "T"),
        shadow_storage = in_flash_or_none(shadow_tables, "T"),
    )
}

/// `OBJECTS`, `SOLID_NODES`, `PALETTE`, `MORE_LIGHTS`, `OPTICS`, `SPHERES`.
fn write_objects<N: Number, C: Config<Number = N>>(scene: &Prepared<C>, out: &mut dyn Write) -> fmt::Result {
    writeln!(out, "pub static OBJECTS: [microtrace::model::Object<Number>; {}] = [", scene.objects.len())?;
    for object in scene.objects.iter() {
        write!(out, "    ")?;
        object_literal(object, out)?;
        writeln!(out, ",")?;
    }
    writeln!(out, "];")?;
    #[cfg(feature = "csg")]
    let solids: &[crate::model::PreparedSolidNode<N>] = &scene.solid_nodes;
    #[cfg(not(feature = "csg"))]
    let solids: &[crate::model::PreparedSolidNode<N>] = &[];
    writeln!(out, "pub static SOLID_NODES: [microtrace::model::PreparedSolidNode<Number>; {}] = [", solids.len())?;
    for node in solids {
        match node {
            crate::model::PreparedSolidNode::Leaf { object, skip_to, top, extent } => {
                write!(out, "    microtrace::model::PreparedSolidNode::Leaf {{ object: ")?;
                object_literal(object, out)?;
                write!(out, ", skip_to: {skip_to}, top: {top}, extent: ")?;
                extent_literal(extent, out)?;
                writeln!(out, " }},")?;
            }
            crate::model::PreparedSolidNode::Combine { operation, left, extent } => {
                write!(out, "    microtrace::model::PreparedSolidNode::Combine {{ operation: microtrace::model::Operation::{operation:?}, left: {left}, extent: ")?;
                extent_literal(extent, out)?;
                writeln!(out, " }},")?;
            }
        }
    }
    writeln!(out, "];")?;
    write!(out, "pub static PALETTE: microtrace::model::Palette = microtrace::model::Palette {{ entries: [")?;
    for entry in scene.palette.entries.iter() {
        write!(out, "microtrace::model::Rgb4 {{ r: {}, g: {}, b: {} }}, ", entry.r, entry.g, entry.b)?;
    }
    writeln!(out, "] }};")?;
    writeln!(out, "pub static MORE_LIGHTS: [microtrace::light::PreparedLightSource<Number>; {}] = [", scene.more_lights.len())?;
    for source in scene.more_lights.iter() {
        write!(out, "    microtrace::light::PreparedLightSource {{ light: ")?;
        light_literal(source.light, out)?;
        write!(out, ", intensity: ")?;
        source.intensity.write_literal(out)?;
        writeln!(out, " }},")?;
    }
    writeln!(out, "];")?;
    #[cfg(feature = "ray-tree")]
    let (optics, spheres) = (&scene.optics[..], &scene.spheres[..]);
    #[cfg(not(feature = "ray-tree"))]
    let (optics, spheres): (&[Optics<N>], &[BoundingSphere<N>]) = (&[], &[]);
    writeln!(out, "pub static OPTICS: [microtrace::scene::Optics<Number>; {}] = [", optics.len())?;
    for o in optics {
        write!(out, "    microtrace::scene::Optics {{ reflect: ")?;
        o.reflect.write_literal(out)?;
        write!(out, ", transmit: ")?;
        o.transmit.write_literal(out)?;
        write!(out, ", ior: ")?;
        o.ior.write_literal(out)?;
        writeln!(out, " }},")?;
    }
    writeln!(out, "];")?;
    writeln!(out, "pub static SPHERES: [microtrace::optimize::bounding_sphere::BoundingSphere<Number>; {}] = [", spheres.len())?;
    for b in spheres {
        write!(out, "    microtrace::optimize::bounding_sphere::BoundingSphere {{ centre: ")?;
        vector(out, b.centre)?;
        write!(out, ", radius: ")?;
        b.radius.write_literal(out)?;
        writeln!(out, " }},")?;
    }
    writeln!(out, "];")
}

/// `GRID_STARTS`, `GRID_POOL` and `GRID_DEPTH`, if there is a grid.
fn write_grid<N: Number, I: Copy + Into<u32>>(grid: Option<GridParts<'_, N, I>>, out: &mut dyn Write) -> fmt::Result {
    let Some(grid) = grid else { return Ok(()) };
    write!(out, "pub static GRID_STARTS: [u16; {}] = ", grid.starts.len())?;
    indices(out, grid.starts)?;
    writeln!(out, ";\npub static GRID_POOL: [microtrace::optimize::grid::Entry<u16>; {}] = [", grid.pool.len())?;
    for entry in grid.pool {
        writeln!(out, "    microtrace::optimize::grid::Entry {{ object: {}, columns: {}, rows: {} }},", entry.object.into(), entry.columns, entry.rows)?;
    }
    writeln!(out, "];")?;
    write!(out, "pub static GRID_DEPTH: [Number; {}] = ", grid.depth.len())?;
    numbers(out, grid.depth)?;
    writeln!(out, ";")
}

/// `HIERARCHY_NODES` and `HIERARCHY_ORDER`, if there is a hierarchy.
fn write_hierarchy<N: Number, I: Copy + Into<u32>>(hierarchy: Option<Bvh<'_, N, I>>, out: &mut dyn Write) -> fmt::Result {
    let Some(hierarchy) = hierarchy else { return Ok(()) };
    writeln!(out, "pub static HIERARCHY_NODES: [microtrace::optimize::bvh::BvhNode<Number>; {}] = [", hierarchy.nodes.len())?;
    for node in hierarchy.nodes {
        write!(out, "    microtrace::optimize::bvh::BvhNode {{ low: ")?;
        numbers(out, &node.low)?;
        write!(out, ", high: ")?;
        numbers(out, &node.high)?;
        writeln!(out, ", first: {}, count: {} }},", node.first, node.count)?;
    }
    writeln!(out, "];")?;
    write!(out, "pub static HIERARCHY_ORDER: [u16; {}] = ", hierarchy.order.len())?;
    indices(out, hierarchy.order)?;
    writeln!(out, ";")
}

/// `SHADOW_CONES_n`, `SHADOW_BLOCKERS_n` and `SHADOW_TABLES`, one light's tables after another
/// (empty: none baked).
fn write_shadow_tables<N: Number>(tables: &[ShadowTables<'_, N>], out: &mut dyn Write) -> fmt::Result {
    for (light, table) in tables.iter().enumerate() {
        writeln!(out, "pub static SHADOW_CONES_{light}: [microtrace::optimize::shadow_culling::DirectionChord<Number>; {}] = [", table.light_cones.len())?;
        for cone in table.light_cones {
            direction_chord(cone, out)?;
        }
        writeln!(out, "];")?;
        writeln!(out, "pub static SHADOW_BLOCKERS_{light}: [microtrace::optimize::shadow_culling::BlockerSet; {}] = [", table.blockers.len())?;
        for set in table.blockers {
            writeln!(out, "    microtrace::optimize::shadow_culling::BlockerSet::from_words({:?}),", BlockerSet::words(*set))?;
        }
        writeln!(out, "];")?;
    }
    writeln!(out, "pub static SHADOW_TABLES: [microtrace::optimize::shadow_culling::ShadowTables<'static, Number>; {}] = [", tables.len())?;
    for light in 0..tables.len() {
        writeln!(out, "    microtrace::optimize::shadow_culling::ShadowTables {{ light_cones: &SHADOW_CONES_{light}, blockers: &SHADOW_BLOCKERS_{light} }},")?;
    }
    writeln!(out, "];")
}

/// The tables that depend on the view: `VIEW_ORDER`, `VIEW_EXTENTS`, `VIEW_NEAR`,
/// `VIEW_STADIUMS`, `VIEW_SHADOW`, `VIEW_EYES`.
fn write_view<N: Number, I: Copy + Into<u32>>(view: &AccelerationParts<'_, N, I>, eyes: &[Vector3<N>], out: &mut dyn Write) -> fmt::Result {
    write!(out, "pub static VIEW_ORDER: [u16; {}] = ", view.order.len())?;
    indices(out, view.order)?;
    writeln!(out, ";\npub static VIEW_EXTENTS: [microtrace::model::Extent; {}] = [", view.extents.len())?;
    for extent in view.extents {
        write!(out, "    ")?;
        extent_literal(extent, out)?;
        writeln!(out, ",")?;
    }
    writeln!(out, "];")?;
    write!(out, "pub static VIEW_NEAR: [Number; {}] = ", view.near.len())?;
    numbers(out, view.near)?;
    writeln!(out, ";")?;
    writeln!(out, "pub static VIEW_STADIUMS: [Option<microtrace::optimize::capsule::Stadium>; {}] = [", view.stadiums.len())?;
    for stadium in view.stadiums {
        match stadium {
            Some(stadium) => writeln!(out, "    Some(microtrace::optimize::capsule::Stadium {{ ends: {:?}, radius: {} }}),", stadium.ends, stadium.radius)?,
            None => writeln!(out, "    None,")?,
        }
    }
    writeln!(out, "];")?;
    writeln!(out, "pub static VIEW_SHADOW: [microtrace::optimize::shadow_culling::ShadowBound<Number>; {}] = [", view.shadow.len())?;
    for bound in view.shadow {
        write!(out, "    ")?;
        shadow_bound_literal(bound, out)?;
        writeln!(out, ",")?;
    }
    writeln!(out, "];")?;
    writeln!(out, "pub static VIEW_EYES: [microtrace::geometry::Vector3<Number>; {}] = [", eyes.len())?;
    for eye in eyes {
        write!(out, "    ")?;
        vector(out, *eye)?;
        writeln!(out, ",")?;
    }
    writeln!(out, "];")
}

/// `SCENE`: the settings, and every table above by reference.
fn write_scene<N: Number, C: Config<Number = N>>(scene: &Prepared<C>, parts: &AccelerationParts<'_, N, C::Index>, out: &mut dyn Write) -> fmt::Result {
    let camera = &scene.camera;
    let (origin, spacing, view_plane) = camera.sampling();
    let v = camera.viewport;
    write!(out, "pub static SCENE: microtrace::bake::BakedScene<'static, Number> = microtrace::bake::BakedScene {{\n    camera: microtrace::camera::Camera::from_parts(microtrace::model::Viewport {{ x1: {}, x2: {}, y1: {}, y2: {} }}, ", v.x1, v.x2, v.y1, v.y2)?;
    numbers(out, &origin)?;
    write!(out, ", ")?;
    numbers(out, &spacing)?;
    write!(out, ", ")?;
    view_plane.write_literal(out)?;
    match camera.eye() {
        Some(eye) => {
            write!(out, ", Some(")?;
            vector(out, eye)?;
            write!(out, "), ")?;
        }
        None => write!(out, ", None, ")?,
    }
    vector(out, camera.parallel_direction().unwrap_or(Vector3::zero()))?;
    write!(out, "),\n    light: ")?;
    light_literal(scene.light, out)?;
    write!(out, ",\n    light_intensity: ")?;
    scene.light_intensity.write_literal(out)?;
    write!(out, ",\n    more_lights: &MORE_LIGHTS,\n    depth: {},\n    antialias: ", scene.depth)?;
    match scene.antialias {
        Some(a) => {
            let v = a.image;
            write!(out, "Some(microtrace::scene::PreparedAntialias {{ image: microtrace::model::Viewport {{ x1: {}, x2: {}, y1: {}, y2: {} }}, levels: {}, threshold: {} }}),", v.x1, v.x2, v.y1, v.y2, a.levels, a.threshold)?
        }
        None => write!(out, "None,")?,
    }
    write!(out, "\n    optics: &OPTICS,\n    spheres: &SPHERES,\n    constants: microtrace::shading::ShadingConstants {{")?;
    let c = &scene.constants;
    for (name, value) in [
        ("fifteen", c.fifteen),
        ("brightest", c.brightest),
        ("half", c.half),
        ("noise_step", c.noise_step),
        ("ambient", c.ambient),
        ("full_rgb", c.full_rgb),
        ("brightest_rgb", c.brightest_rgb),
    ] {
        write!(out, " {name}: ")?;
        value.write_literal(out)?;
        write!(out, ",")?;
    }
    let o = scene.optimizations;
    writeln!(
        out,
        " }},\n    background: {},\n    shadows: {},\n    dither: {},\n    optimizations: microtrace::model::Optimizations {{ pixelbuffer: {}, extents: {}, grid: {}, sortlist: {} }},",
        scene.background, scene.shadows, scene.dither, o.pixelbuffer, o.extents, o.grid, o.sortlist
    )?;
    writeln!(out, "    palette: &PALETTE,\n    eyes: &VIEW_EYES,\n    acceleration: microtrace::optimize::AccelerationParts {{ order: &VIEW_ORDER, extents: &VIEW_EXTENTS, near: &VIEW_NEAR, stadiums: &VIEW_STADIUMS, shadow: &VIEW_SHADOW,")?;
    match parts.grid {
        Some(grid) => writeln!(
            out,
            "        grid: Some(microtrace::optimize::grid::GridParts {{ width: core::num::NonZeroU16::new({}).unwrap(), height: core::num::NonZeroU16::new({}).unwrap(), side: {}, starts: &GRID_STARTS, pool: &GRID_POOL, depth: &GRID_DEPTH }}),",
            grid.width, grid.height, grid.side
        )?,
        None => writeln!(out, "        grid: None,")?,
    }
    match parts.hierarchy {
        Some(_) => writeln!(out, "        hierarchy: Some(microtrace::optimize::bvh::Bvh {{ nodes: &HIERARCHY_NODES, order: &HIERARCHY_ORDER }}),")?,
        None => writeln!(out, "        hierarchy: None,")?,
    }
    writeln!(out, "        shadow_tables: &SHADOW_TABLES,\n    }},\n}};")
}

fn light_literal<N: Number>(light: PreparedLight<N>, out: &mut dyn Write) -> fmt::Result {
    let (kind, position) = match light {
        PreparedLight::Point(position) => ("Point", position),
        PreparedLight::Direction(direction) => ("Direction", direction),
    };
    write!(out, "microtrace::light::PreparedLight::{kind}(")?;
    vector(out, position)?;
    write!(out, ")")
}

fn shadow_bound_literal<N: Number>(bound: &ShadowBound<N>, out: &mut dyn Write) -> fmt::Result {
    write!(out, "microtrace::optimize::shadow_culling::ShadowBound {{ centre: ")?;
    vector(out, bound.centre)?;
    write!(out, ", axis: ")?;
    vector(out, bound.axis)?;
    for (name, value) in [("half", bound.half), ("radius", bound.radius), ("reach", bound.reach)] {
        write!(out, ", {name}: ")?;
        value.write_literal(out)?;
    }
    write!(out, " }}")
}

fn direction_chord<N: Number>(cone: &DirectionChord<N>, out: &mut dyn Write) -> fmt::Result {
    write!(out, "    microtrace::optimize::shadow_culling::DirectionChord {{ start: ")?;
    vector(out, cone.start)?;
    write!(out, ", along: ")?;
    vector(out, cone.along)?;
    for (name, value) in [("inverse_squared", cone.inverse_squared), ("reach_squared", cone.reach_squared), ("cosine", cone.cosine)] {
        write!(out, ", {name}: ")?;
        value.write_literal(out)?;
    }
    writeln!(out, ", low: {:?}, high: {:?} }},", cone.low, cone.high)
}

fn indices<I: Copy + Into<u32>>(out: &mut dyn Write, values: &[I]) -> fmt::Result {
    write!(out, "[")?;
    for (index, value) in values.iter().enumerate() {
        if index > 0 {
            write!(out, ", ")?;
        }
        write!(out, "{}", (*value).into())?;
    }
    write!(out, "]")
}

fn numbers<N: Number>(out: &mut dyn Write, values: &[N]) -> fmt::Result {
    write!(out, "[")?;
    for (index, value) in values.iter().enumerate() {
        if index > 0 {
            write!(out, ", ")?;
        }
        value.write_literal(out)?;
    }
    write!(out, "]")
}

fn vector<N: Number>(out: &mut dyn Write, v: Vector3<N>) -> fmt::Result {
    write!(out, "microtrace::geometry::Vector3 {{ x: ")?;
    v.x.write_literal(out)?;
    write!(out, ", y: ")?;
    v.y.write_literal(out)?;
    write!(out, ", z: ")?;
    v.z.write_literal(out)?;
    write!(out, " }}")
}

/// One prepared object as a Rust literal, every number bit for bit.
fn object_literal<N: Number>(object: &Object<N>, out: &mut dyn Write) -> fmt::Result {
    let columns = object.object_from_world.columns();
    write!(out, "microtrace::model::Object {{ primitive: ")?;
    primitive_path(object.primitive, out)?;
    write!(out, ", object_from_world: microtrace::geometry::AffineTransform::from_parts([")?;
    for column in columns {
        numbers(out, &column)?;
        write!(out, ", ")?;
    }
    write!(out, "], ")?;
    numbers(out, &object.object_from_world.translation)?;
    let m = &object.material;
    write!(out, "), material: microtrace::model::PreparedMaterial {{ colour: {}, ka: ", m.colour)?;
    m.ka.write_literal(out)?;
    write!(out, ", kd: ")?;
    m.kd.write_literal(out)?;
    write!(out, ", ks: ")?;
    m.ks.write_literal(out)?;
    write!(out, ", rnd: ")?;
    m.rnd.write_literal(out)?;
    write!(out, ", power: {}, reflectance: ", m.power)?;
    numbers(out, &m.reflectance)?;
    write!(out, " }} }}")
}

/// The primitive as a Rust expression (a torus with its tube in steps, a solid with its range).
fn primitive_path(primitive: Primitive, out: &mut dyn Write) -> fmt::Result {
    match primitive {
        Primitive::Torus(tube) => write!(out, "microtrace::model::Primitive::Torus(microtrace::model::Tube::from_steps({}))", tube.steps()),
        #[cfg(feature = "triangle")]
        Primitive::Patch(normals) => write!(out, "microtrace::model::Primitive::Patch(microtrace::model::VertexNormals({:?}))", normals.0),
        Primitive::Frustum(taper) => write!(out, "microtrace::model::Primitive::Frustum(microtrace::model::Taper::from_steps({}))", taper.steps()),
        Primitive::Solid(range) => write!(out, "microtrace::model::Primitive::Solid(microtrace::model::SolidRange {{ first: {}, count: {} }})", range.first, range.count),
        other => write!(out, "microtrace::model::Primitive::{other:?}"),
    }
}

/// A screen extent as a Rust expression.
fn extent_literal(extent: &Extent, out: &mut dyn Write) -> fmt::Result {
    let Extent { first_column, last_column, first_row, last_row, diagonal } = extent;
    write!(out, "microtrace::model::Extent {{ first_column: {first_column}, last_column: {last_column}, first_row: {first_row}, last_row: {last_row}, diagonal: {diagonal:?} }}")
}
