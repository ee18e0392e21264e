//! A scene prepared ahead: everything that depends on the scene alone (the objects' inverse
//! transforms and materials, their bounding and shadow capsules, the camera, the light, the
//! shading constants) made on the host in the number type and written as Rust source
//! ([`write_prepared_ahead`], the firmware's build script), so that it reaches flash already in
//! the number type; and the chip's preparation from it ([`Scene::prepare_ahead`]), which does
//! only what depends on the view and the light, with no `f64` at all.

use core::fmt::{self, Write};

use crate::camera::Camera;
use crate::geometry::Vector3;
use crate::number::Number;
use crate::optimize::bounding_sphere::BoundingSphere;
use crate::optimize::{ObjectBounds, ViewAhead};
use crate::optimize::grid::GridAhead;
use crate::optimize::shadow_culling::{BlockerSet, DirectionChord, ShadowTablesAhead};
#[cfg(feature = "acceleration-tables")]
use crate::optimize::bvh::Bvh;
use crate::model::{SceneError, SceneErrorKind};
use crate::model::{Optimizations, Primitive};
use crate::light::{PreparedLight, PreparedLightSource};
use crate::config::{Config, PaletteStorage};
#[cfg(feature = "ray-tree")]
use crate::storage::List;
use crate::scene::{Optics, Prepared, PreparedAntialias};
use crate::model::Palette;
use crate::shading::ShadingConstants;

/// The parts of a scene prepared ahead, as the firmware keeps them in flash (`I`: its tables'
/// index type).
#[derive(Debug)]
pub struct PreparedAhead<'a, N, I = u16> {
    pub camera: Camera<N>,
    pub light: PreparedLight<N>,
    pub light_intensity: N,
    pub more_lights: &'a [PreparedLightSource<N>],
    pub depth: u8,
    pub antialias: Option<PreparedAntialias>,
    /// The ray tree's per-object parts (empty when no object reflects or transmits).
    #[cfg(feature = "ray-tree")]
    pub optics: &'a [Optics<N>],
    #[cfg(feature = "ray-tree")]
    pub spheres: &'a [BoundingSphere<N>],
    pub constants: ShadingConstants<N>,
    pub background: u8,
    pub shadows: bool,
    pub dither: bool,
    pub optimizations: Optimizations,
    pub palette: &'a Palette,
    pub bounds: &'a [ObjectBounds<N>],
    /// The shadow and secondary rays' hierarchy of boxes, for a scene of many objects
    /// ([`crate::optimize::hierarchy_ahead`]).
    #[cfg(feature = "acceleration-tables")]
    pub hierarchy: Option<Bvh<'a, N, I>>,
    #[cfg(not(feature = "acceleration-tables"))]
    pub hierarchy: Option<core::marker::PhantomData<&'a I>>,
    /// The screen grid for the view above ([`crate::optimize::Acceleration::grid_parts`] of
    /// the scene prepared on the host from the same bounds): preparation builds none.
    pub grid: Option<GridAhead<'a, N, I>>,
    /// The lights' shadow tables for this view, one per light (empty: none made; the render's
    /// `render::shadow_tables::tables_ahead` makes them on the host): the render builds none.
    pub shadow_tables: &'a [ShadowTablesAhead<'a, N>],
    /// The per-object tables that depend on the view, made for this view
    /// ([`crate::optimize::Acceleration::view_parts`] of the scene prepared on the host from the
    /// same bounds): preparation makes none, and `bounds` is then empty.
    pub view: Option<ViewAhead<'a, N, I>>,
}

impl<N: Number, C: Config<Number = N>> Prepared<C> {
    /// Prepares the scene in place from parts made ahead: copies them, puts the eye into the
    /// space of each of the scene's objects (already prepared ahead too) and builds the acceleration structures from the bounds (per frame: the
    /// work that depends on the view and the light).
    pub fn prepare_ahead(&mut self, parts: &PreparedAhead<'static, N, C::Index>) -> Result<(), SceneError> {
        let too_many = |capacity| SceneError { line: 0, kind: SceneErrorKind::TooManyObjects { capacity } };
        self.camera = parts.camera;
        self.light = parts.light;
        self.light_intensity = parts.light_intensity;
        crate::storage::List::clear(&mut self.more_lights);
        for source in parts.more_lights {
            let capacity = <C::OtherLights<PreparedLightSource<N>> as crate::storage::List<_>>::CAPACITY.saturating_add(1);
            crate::storage::List::push(&mut self.more_lights, *source).map_err(|_| SceneError { line: 0, kind: SceneErrorKind::TooManyLights { capacity } })?;
        }
        self.depth = parts.depth;
        self.antialias = parts.antialias;
        #[cfg(feature = "ray-tree")]
        {
            self.optics.clear();
            self.spheres.clear();
            for optics in parts.optics {
                self.optics.push(*optics).map_err(|_| too_many(C::MAX_OBJECTS))?;
            }
            for sphere in parts.spheres {
                self.spheres.push(*sphere).map_err(|_| too_many(C::MAX_OBJECTS))?;
            }
            self.space_grid.build(&self.spheres);
            self.transparent = self.optics.iter().any(|optics| optics.transmit > N::ZERO);
        }
        self.constants = parts.constants;
        self.background = parts.background;
        self.shadows = parts.shadows;
        self.dither = parts.dither;
        self.optimizations = parts.optimizations;
        self.palette.hold(parts.palette);
        // The objects are the scene's own (the firmware's in flash, `OBJECTS_AHEAD`): only their
        // eyes are placed, as they depend on the view.
        if self.objects.len() > C::MAX_OBJECTS {
            return Err(too_many(C::MAX_OBJECTS));
        }
        #[cfg(feature = "acceleration-tables")]
        self.acceleration.hold_hierarchy_ahead(parts.hierarchy);
        self.acceleration.hold_grid_ahead(parts.grid);
        self.acceleration.hold_shadow_tables_ahead(parts.shadow_tables);
        match parts.view.filter(|_| C::VIEW_AHEAD) {
            // Made ahead for this view: nothing to place or build.
            Some(view) => self.acceleration.hold_view_ahead(&self.camera, self.optimizations, view),
            None => {
                self.place_eyes();
                self.acceleration.rebuild_from_bounds(&self.camera, self.optimizations, parts.bounds);
            }
        }
        Ok(())
    }
}

/// Writes the Rust source of `scene`'s parts prepared ahead: `OBJECTS_AHEAD`, `BOUNDS_AHEAD`,
/// `PALETTE_AHEAD`, `HIERARCHY_AHEAD`, `GRID_AHEAD` and `AHEAD` (a [`PreparedAhead`]), the
/// number type named `Number` where it is written (every value bit for bit, by
/// [`Number::write_literal`]).
pub fn write_prepared_ahead<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    bounds: &[ObjectBounds<N>],
    hierarchy: Hierarchy<'_, N>,
    grid: Option<GridAhead<'_, N, u16>>,
    shadow_tables: &[ShadowTablesAhead<'_, N>],
    view: Option<ViewAhead<'_, N, u16>>,
    out: &mut dyn Write,
) -> fmt::Result {
    let count = scene.objects.len();
    writeln!(out, "pub static OBJECTS_AHEAD: [microtrace::model::Object<Number>; {count}] = [")?;
    for object in scene.objects.iter() {
        write!(out, "    ")?;
        object_literal(object, out)?;
        writeln!(out, ",")?;
    }
    writeln!(out, "];")?;
    // The solids' nodes, in flash like the objects (empty without solids).
    #[cfg(feature = "csg")]
    let solids: &[crate::model::PreparedSolidNode<N>] = &scene.solid_nodes;
    #[cfg(not(feature = "csg"))]
    let solids: &[crate::model::PreparedSolidNode<N>] = &[];
    writeln!(out, "pub static SOLID_NODES_AHEAD: [microtrace::model::PreparedSolidNode<Number>; {}] = [", solids.len())?;
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
    // With the view's tables made ahead the chip never reads the bounds: none are written.
    let bounds = if view.is_some() { &[] } else { bounds };
    writeln!(out, "pub static BOUNDS_AHEAD: [microtrace::optimize::ObjectBounds<Number>; {}] = [", bounds.len())?;
    for b in bounds {
        write!(out, "    microtrace::optimize::ObjectBounds {{ primitive: ")?;
        primitive_path(b.primitive, out)?;
        write!(out, ", capsule: microtrace::optimize::capsule::Capsule {{ start: ")?;
        vector(out, b.capsule.start)?;
        write!(out, ", end: ")?;
        vector(out, b.capsule.end)?;
        write!(out, ", radius: ")?;
        b.capsule.radius.write_literal(out)?;
        write!(out, " }}, shadow: ")?;
        shadow_bound_literal(&b.shadow, out)?;
        writeln!(out, " }},")?;
    }
    writeln!(out, "];")?;
    write_tree_ahead(scene, out)?;
    write!(out, "pub static PALETTE_AHEAD: microtrace::model::Palette = microtrace::model::Palette {{ entries: [")?;
    for entry in scene.palette.entries.iter() {
        write!(out, "microtrace::model::Rgb4 {{ r: {}, g: {}, b: {} }}, ", entry.r, entry.g, entry.b)?;
    }
    writeln!(out, "] }};")?;
    let hierarchy = if write_hierarchy(hierarchy, out)? { "Some(HIERARCHY_AHEAD)" } else { "None" };
    let grid = if write_grid(grid, out)? { "Some(GRID_AHEAD)" } else { "None" };
    write_shadow_tables(shadow_tables, out)?;
    let view = if write_view(view, out)? { "Some(VIEW_AHEAD)" } else { "None" };
    let camera = &scene.camera;
    let (origin, spacing, view_plane) = camera.sampling();
    let v = camera.viewport;
    write!(out, "pub static AHEAD: microtrace::scene::ahead::PreparedAhead<'static, Number> = microtrace::scene::ahead::PreparedAhead {{\n    camera: microtrace::camera::Camera::from_parts(microtrace::model::Viewport {{ x1: {}, x2: {}, y1: {}, y2: {} }}, ", v.x1, v.x2, v.y1, v.y2)?;
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
    write!(out, "),\n    light: microtrace::light::PreparedLight::")?;
    let (kind, position) = match scene.light {
        PreparedLight::Point(position) => ("Point", position),
        PreparedLight::Direction(direction) => ("Direction", direction),
    };
    write!(out, "{kind}(")?;
    vector(out, position)?;
    write!(out, "),\n    light_intensity: ")?;
    scene.light_intensity.write_literal(out)?;
    write!(out, ",\n    more_lights: &MORE_LIGHTS_AHEAD,\n    depth: {},\n    antialias: ", scene.depth)?;
    match scene.antialias {
        Some(a) => {
            let v = a.image;
            write!(out, "Some(microtrace::scene::PreparedAntialias {{ image: microtrace::model::Viewport {{ x1: {}, x2: {}, y1: {}, y2: {} }}, levels: {}, threshold: {} }}),", v.x1, v.x2, v.y1, v.y2, a.levels, a.threshold)?
        }
        None => write!(out, "None,")?,
    }
    // The tree's parts exist in a firmware built with the core's `ray-tree` feature (its own
    // feature of that name); a scene that needs them fails the build without it.
    write!(out, "\n    #[cfg(feature = \"ray-tree\")]\n    optics: &OPTICS_AHEAD,\n    #[cfg(feature = \"ray-tree\")]\n    spheres: &SPHERES_AHEAD,")?;
    write!(out, "\n    constants: microtrace::shading::ShadingConstants {{")?;
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
    writeln!(out, "    palette: &PALETTE_AHEAD,\n    bounds: &BOUNDS_AHEAD,\n    hierarchy: {hierarchy},\n    grid: {grid},\n    shadow_tables: &SHADOW_TABLES_AHEAD,\n    view: {view},\n}};")
}

/// `GRID_AHEAD` and its tables (the cells' starts, the entries and their depth bounds), if
/// there is a grid; whether there is.
fn write_grid<N: Number>(grid: Option<GridAhead<'_, N, u16>>, out: &mut dyn Write) -> Result<bool, fmt::Error> {
    let Some(grid) = grid else { return Ok(false) };
    writeln!(out, "pub static GRID_STARTS_AHEAD: [u16; {}] = {:?};", grid.starts.len(), grid.starts)?;
    writeln!(out, "pub static GRID_POOL_AHEAD: [microtrace::optimize::grid::Entry<u16>; {}] = [", grid.pool.len())?;
    for entry in grid.pool {
        writeln!(out, "    microtrace::optimize::grid::Entry {{ object: {}, columns: {}, rows: {} }},", entry.object, entry.columns, entry.rows)?;
    }
    writeln!(out, "];")?;
    write!(out, "pub static GRID_DEPTH_AHEAD: [Number; {}] = ", grid.depth.len())?;
    numbers(out, grid.depth)?;
    writeln!(out, ";")?;
    writeln!(
        out,
        "pub const GRID_AHEAD: microtrace::optimize::grid::GridAhead<'static, Number, u16> = microtrace::optimize::grid::GridAhead {{ width: core::num::NonZeroU16::new({}).unwrap(), height: core::num::NonZeroU16::new({}).unwrap(), side: {}, starts: &GRID_STARTS_AHEAD, pool: &GRID_POOL_AHEAD, depth: &GRID_DEPTH_AHEAD }};",
        grid.width, grid.height, grid.side
    )?;
    Ok(true)
}

/// `SHADOW_TABLES_AHEAD`, one light's tables after another (empty: none made ahead).
fn write_shadow_tables<N: Number>(tables: &[ShadowTablesAhead<'_, N>], out: &mut dyn Write) -> fmt::Result {
    for (light, table) in tables.iter().enumerate() {
        writeln!(out, "pub static SHADOW_CONES_AHEAD_{light}: [microtrace::optimize::shadow_culling::DirectionChord<Number>; {}] = [", table.light_cones.len())?;
        for cone in table.light_cones {
            direction_chord(cone, out)?;
        }
        writeln!(out, "];")?;
        writeln!(out, "pub static SHADOW_BLOCKERS_AHEAD_{light}: [microtrace::optimize::shadow_culling::BlockerSet; {}] = [", table.blockers.len())?;
        for set in table.blockers {
            writeln!(out, "    microtrace::optimize::shadow_culling::BlockerSet::from_words({:?}),", BlockerSet::words(*set))?;
        }
        writeln!(out, "];")?;
    }
    writeln!(out, "pub static SHADOW_TABLES_AHEAD: [microtrace::optimize::shadow_culling::ShadowTablesAhead<'static, Number>; {}] = [", tables.len())?;
    for light in 0..tables.len() {
        writeln!(out, "    microtrace::optimize::shadow_culling::ShadowTablesAhead {{ light_cones: &SHADOW_CONES_AHEAD_{light}, blockers: &SHADOW_BLOCKERS_AHEAD_{light} }},")?;
    }
    writeln!(out, "];")
}

/// `VIEW_AHEAD` and its tables, if the view's tables are made ahead; whether they are.
fn write_view<N: Number>(view: Option<ViewAhead<'_, N, u16>>, out: &mut dyn Write) -> Result<bool, fmt::Error> {
    let Some(view) = view else { return Ok(false) };
    writeln!(out, "pub static VIEW_ORDER_AHEAD: [u16; {}] = {:?};", view.order.len(), view.order)?;
    writeln!(out, "pub static VIEW_EXTENTS_AHEAD: [microtrace::model::Extent; {}] = [", view.extents.len())?;
    for extent in view.extents {
        write!(out, "    ")?;
        extent_literal(extent, out)?;
        writeln!(out, ",")?;
    }
    writeln!(out, "];")?;
    write!(out, "pub static VIEW_NEAR_AHEAD: [Number; {}] = ", view.near.len())?;
    numbers(out, view.near)?;
    writeln!(out, ";")?;
    writeln!(out, "pub static VIEW_STADIUMS_AHEAD: [Option<microtrace::optimize::capsule::Stadium>; {}] = [", view.stadiums.len())?;
    for stadium in view.stadiums {
        match stadium {
            Some(stadium) => writeln!(out, "    Some(microtrace::optimize::capsule::Stadium {{ ends: {:?}, radius: {} }}),", stadium.ends, stadium.radius)?,
            None => writeln!(out, "    None,")?,
        }
    }
    writeln!(out, "];")?;
    writeln!(out, "pub static VIEW_SHADOW_AHEAD: [microtrace::optimize::shadow_culling::ShadowBound<Number>; {}] = [", view.shadow.len())?;
    for bound in view.shadow {
        write!(out, "    ")?;
        shadow_bound_literal(bound, out)?;
        writeln!(out, ",")?;
    }
    writeln!(out, "];")?;
    writeln!(out, "pub static VIEW_EYES_AHEAD: [microtrace::geometry::Vector3<Number>; {}] = [", view.eyes.len())?;
    for eye in view.eyes {
        write!(out, "    ")?;
        vector(out, *eye)?;
        writeln!(out, ",")?;
    }
    writeln!(out, "];")?;
    writeln!(
        out,
        "pub const VIEW_AHEAD: microtrace::optimize::ViewAhead<'static, Number, u16> = microtrace::optimize::ViewAhead {{ order: &VIEW_ORDER_AHEAD, extents: &VIEW_EXTENTS_AHEAD, near: &VIEW_NEAR_AHEAD, stadiums: &VIEW_STADIUMS_AHEAD, shadow: &VIEW_SHADOW_AHEAD, eyes: &VIEW_EYES_AHEAD }};"
    )?;
    Ok(true)
}

fn shadow_bound_literal<N: Number>(bound: &crate::optimize::shadow_culling::ShadowBound<N>, out: &mut dyn Write) -> fmt::Result {
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

/// A hierarchy made ahead: its nodes and its leaves' objects (the firmware's index, `u16`).
#[cfg(feature = "acceleration-tables")]
pub type Hierarchy<'a, N> = Option<Bvh<'a, N, u16>>;
#[cfg(not(feature = "acceleration-tables"))]
pub type Hierarchy<'a, N> = Option<core::marker::PhantomData<&'a N>>;

/// `HIERARCHY_AHEAD` and its tables, if there is a hierarchy; whether there is.
#[cfg(feature = "acceleration-tables")]
fn write_hierarchy<N: Number>(hierarchy: Hierarchy<'_, N>, out: &mut dyn Write) -> Result<bool, fmt::Error> {
    let Some(hierarchy) = hierarchy else { return Ok(false) };
    writeln!(out, "pub static HIERARCHY_NODES_AHEAD: [microtrace::optimize::bvh::BvhNode<Number>; {}] = [", hierarchy.nodes.len())?;
    for node in hierarchy.nodes {
        write!(out, "    microtrace::optimize::bvh::BvhNode {{ low: ")?;
        numbers(out, &node.low)?;
        write!(out, ", high: ")?;
        numbers(out, &node.high)?;
        writeln!(out, ", first: {}, count: {} }},", node.first, node.count)?;
    }
    writeln!(out, "];")?;
    writeln!(out, "pub static HIERARCHY_ORDER_AHEAD: [u16; {}] = {:?};", hierarchy.order.len(), hierarchy.order)?;
    writeln!(out, "pub const HIERARCHY_AHEAD: microtrace::optimize::bvh::Bvh<'static, Number, u16> = microtrace::optimize::bvh::Bvh {{ nodes: &HIERARCHY_NODES_AHEAD, order: &HIERARCHY_ORDER_AHEAD }};")?;
    Ok(true)
}

#[cfg(not(feature = "acceleration-tables"))]
fn write_hierarchy<N: Number>(_hierarchy: Hierarchy<'_, N>, _out: &mut dyn Write) -> Result<bool, fmt::Error> {
    Ok(false)
}

/// `MORE_LIGHTS_AHEAD`, and `OPTICS_AHEAD` and `SPHERES_AHEAD` (the ray tree's, empty without it).
fn write_tree_ahead<N: Number, C: Config<Number = N>>(scene: &Prepared<C>, out: &mut dyn Write) -> fmt::Result {
    writeln!(out, "pub static MORE_LIGHTS_AHEAD: [microtrace::light::PreparedLightSource<Number>; {}] = [", scene.more_lights.len())?;
    for source in scene.more_lights.iter() {
        let (kind, position) = match source.light {
            PreparedLight::Point(position) => ("Point", position),
            PreparedLight::Direction(direction) => ("Direction", direction),
        };
        write!(out, "    microtrace::light::PreparedLightSource {{ light: microtrace::light::PreparedLight::{kind}(")?;
        vector(out, position)?;
        write!(out, "), intensity: ")?;
        source.intensity.write_literal(out)?;
        writeln!(out, " }},")?;
    }
    writeln!(out, "];")?;
    #[cfg(feature = "ray-tree")]
    let (optics, spheres) = (&scene.optics[..], &scene.spheres[..]);
    #[cfg(not(feature = "ray-tree"))]
    let (optics, spheres): (&[Optics<N>], &[BoundingSphere<N>]) = (&[], &[]);
    writeln!(out, "#[cfg(feature = \"ray-tree\")]\npub static OPTICS_AHEAD: [microtrace::scene::Optics<Number>; {}] = [", optics.len())?;
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
    writeln!(out, "#[cfg(feature = \"ray-tree\")]\npub static SPHERES_AHEAD: [microtrace::optimize::bounding_sphere::BoundingSphere<Number>; {}] = [", spheres.len())?;
    for b in spheres {
        write!(out, "    microtrace::optimize::bounding_sphere::BoundingSphere {{ centre: ")?;
        vector(out, b.centre)?;
        write!(out, ", radius: ")?;
        b.radius.write_literal(out)?;
        writeln!(out, " }},")?;
    }
    writeln!(out, "];")
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
fn object_literal<N: Number>(object: &crate::model::Object<N>, out: &mut dyn Write) -> fmt::Result {
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
fn extent_literal(extent: &crate::model::Extent, out: &mut dyn Write) -> fmt::Result {
    let crate::model::Extent { first_column, last_column, first_row, last_row, diagonal } = extent;
    write!(out, "microtrace::model::Extent {{ first_column: {first_column}, last_column: {last_column}, first_row: {first_row}, last_row: {last_row}, diagonal: {diagonal:?} }}")
}
