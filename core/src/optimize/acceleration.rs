//! What the optimizations derive from the objects' bounding volumes at preparation (§4.7,
//! `preprocess`): the screen map, the extents, the grid, the Sortlist order and the shadow
//! bounds, rebuilt when the view changes.

use crate::camera::{Camera, PixelPosition};
use crate::geometry::{AffineTransform, Vector3};
use crate::config::Config;
use crate::storage::{Index, Table, Unset};
use crate::number::Number;
use crate::model::{ObjectDescription, Optimizations, Primitive};

use super::bounding_volume::ObjectGeometry;
use super::capsule::{Capsule, ScreenMap};
use super::extents::Extent;
use super::grid::{Grid, GridParts};
use super::projection::Screen;
use super::build_options::SILHOUETTES;
use super::shadow_culling::{ShadowBound, ShadowTables};
use super::bvh::Bvh;
#[cfg(feature = "acceleration-tables")]
use super::bvh::BvhNode;
use super::{capsule, grid, projection, shadow_culling, sortlist};

/// Choices beyond the thesis; [`Tuning::IMPROVED`] is the default, [`Tuning::THESIS`] is the
/// thesis's own algorithms (the 8-vertex volumes, the extent grid, shadow rays unculled).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tuning {
    /// Silhouettes from 16-gons circumscribed about rims and caps, not the 8-vertex volumes.
    pub tight_silhouettes: bool,
    /// Grid membership by silhouette, with the silhouette's rectangle within each cell.
    pub cell_rectangles: bool,
    /// Shadow rays skip objects whose bounding sphere they miss, and try the last blocker
    /// first (with Extents on).
    pub shadow_culling: bool,
    /// Each primary ray first tests the object the previous ray hit (when the pixel is in its
    /// extent), so Sortlist's exit comes at once where the surface continues.
    pub hit_cache: bool,
}

impl Tuning {
    pub const IMPROVED: Self = Self { tight_silhouettes: true, cell_rectangles: true, shadow_culling: true, hit_cache: true };
    pub const THESIS: Self = Self { tight_silhouettes: false, cell_rectangles: false, shadow_culling: false, hit_cache: false };
}

/// What the optimizations derive per object from the bounding volumes at preprocess time.
/// Per object: its place in the test order (a `Config::Index`), its extent (4 `u16`), a depth bound (`N`)
/// and a shadow bounding capsule (8 `N`); per scene: the grid. Each table is the `Config`'s
/// storage: built here into RAM, or a baked scene's in flash ([`Acceleration::hold_parts`]).
pub struct Acceleration<C: Config> {
    count: usize,
    optimizations: Optimizations,
    tuning: Tuning,
    screen: Screen,
    /// Test order: sorted by depth bound with Sortlist, object order otherwise.
    order: C::ViewTable<C::Index>,
    extents: C::ViewTable<Extent>,
    /// Lower bound of the `t` of any hit on each object (`−N::MAX`: none known).
    near: C::ViewTable<C::Number>,
    /// Each object's silhouette as a stadium (our tuning), for the grid and the fill.
    stadiums: C::ViewTable<Option<capsule::Stadium>>,
    #[cfg(feature = "acceleration-tables")]
    shadow: C::ViewTable<ShadowBound<C::Number>>,
    /// The shadow rays' hierarchy (`Config::HIERARCHY`, more than 128 objects, or baked): its
    /// nodes, the objects of its leaves, and how many nodes are in use (0: none).
    #[cfg(feature = "acceleration-tables")]
    hierarchy: C::Hierarchy<BvhNode<C::Number>>,
    #[cfg(feature = "acceleration-tables")]
    hierarchy_order: C::Hierarchy<C::Index>,
    #[cfg(feature = "acceleration-tables")]
    hierarchy_nodes: usize,
    grid: Grid<C>,
    /// The lights' shadow tables kept with the scene (a baked scene's: `Config::LightTables`),
    /// one per light; none where a render builds its own.
    shadow_tables: C::LightTables<ShadowTables<'static, C::Number>>,
}

/// The tables that depend on the view by their parts, borrowed: what a preparation for a view
/// builds ([`Acceleration::parts`]), and what a scene baked for a fixed view and light keeps in
/// flash and reads in their place ([`Acceleration::hold_parts`]) — the test order and each
/// object's extent, depth bound, stadium and shadow capsule; the screen grid and the shadow
/// rays' hierarchy where there are; each light's shadow tables where a render builds them.
#[derive(Clone, Copy, Debug)]
pub struct AccelerationParts<'a, N, I> {
    pub order: &'a [I],
    pub extents: &'a [Extent],
    pub near: &'a [N],
    pub stadiums: &'a [Option<capsule::Stadium>],
    pub shadow: &'a [ShadowBound<N>],
    /// The screen grid (`None`: none in use).
    pub grid: Option<GridParts<'a, N, I>>,
    /// The shadow and secondary rays' hierarchy (`None`: none in use).
    pub hierarchy: Option<Bvh<'a, N, I>>,
    /// Each light's shadow tables (empty: none made, or none a render would build).
    pub shadow_tables: &'a [ShadowTables<'a, N>],
}

impl<C: Config> core::fmt::Debug for Acceleration<C> {
    fn fmt(&self, formatter: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        formatter.debug_struct("Acceleration").field("count", &self.count).field("optimizations", &self.optimizations).field("tuning", &self.tuning).field("grid", &self.grid).finish_non_exhaustive()
    }
}

impl<C: Config> Clone for Acceleration<C> {
    fn clone(&self) -> Self {
        Self {
            count: self.count,
            optimizations: self.optimizations,
            tuning: self.tuning,
            screen: self.screen,
            order: self.order.clone(),
            extents: self.extents.clone(),
            near: self.near.clone(),
            stadiums: self.stadiums.clone(),
            #[cfg(feature = "acceleration-tables")]
            shadow: self.shadow.clone(),
            #[cfg(feature = "acceleration-tables")]
            hierarchy: self.hierarchy.clone(),
            #[cfg(feature = "acceleration-tables")]
            hierarchy_order: self.hierarchy_order.clone(),
            #[cfg(feature = "acceleration-tables")]
            hierarchy_nodes: self.hierarchy_nodes,
            grid: self.grid.clone(),
            shadow_tables: self.shadow_tables.clone(),
        }
    }
}

impl<C: Config> Acceleration<C> {
    /// Every byte zero, nothing built: the value before [`Acceleration::rebuild`] (a `static`
    /// holding it costs zero-initialised RAM and no flash).
    pub const UNSET: Self = Self {
        count: 0,
        optimizations: Optimizations::NONE,
        tuning: Tuning::THESIS,
        screen: Screen::UNSET,
        order: Unset::UNSET,
        extents: Unset::UNSET,
        near: Unset::UNSET,
        stadiums: Unset::UNSET,
        #[cfg(feature = "acceleration-tables")]
        shadow: Unset::UNSET,
        #[cfg(feature = "acceleration-tables")]
        hierarchy: Unset::UNSET,
        #[cfg(feature = "acceleration-tables")]
        hierarchy_order: Unset::UNSET,
        #[cfg(feature = "acceleration-tables")]
        hierarchy_nodes: 0,
        grid: Grid::UNSET,
        shadow_tables: Unset::UNSET,
    };
}

/// The hierarchy's storage: boxes (references to objects, `early_split`) per object.
#[cfg(feature = "acceleration-tables")]
const REFERENCES_PER_OBJECT: usize = 2;

/// A host's scene of more objects than this gets a hierarchy of boxes for its shadow and
/// secondary rays in place of the blocker sets and the space grid (docs/pipeline.md, measured
/// side by side, `f32`: balls2's 93 objects and rings1's 62 gain, the thesis lattice's 54 loses
/// (its 27 rods span the scene, so the hierarchy's boxes overlap: 1.6 times the trace), and
/// tree3's 32, lattice1's 20 and balls1's 12 lose). A count stands in for what decides, the
/// boxes' overlap against the sets' sizes.
pub const HIERARCHY_ABOVE: usize = 60;

/// A baked scene of more objects than this gets one, baked ([`baked_hierarchy`]):
/// the blocker sets' capacity. Below it the sets cost the Cortex-M4F less than the walk (balls2,
/// 93 objects: 120.6 M instructions a frame with them, 140.6 M with the hierarchy); above it the
/// per-object shadow tables the sets need fill the stack (tree-s6, 256 objects and 7 lights:
/// 157,840 bytes of RAM without, it runs in 64 KB with).
#[cfg(feature = "acceleration-tables")]
pub const BAKED_HIERARCHY_ABOVE: usize = super::shadow_culling::BlockerSet::CAPACITY;

impl<N: Number, C: Config<Number = N>> Acceleration<C> {
    /// Nothing built, tables for `count` objects (as many as an array holds): [`Acceleration::UNSET`]
    /// for storage sized at run time.
    pub fn unset(count: usize) -> Self {
        Self {
            count: 0,
            optimizations: Optimizations::NONE,
            tuning: Tuning::THESIS,
            screen: Screen::UNSET,
            order: C::ViewTable::filled(count, C::Index::default()),
            extents: C::ViewTable::filled(count, Extent { first_column: 0, last_column: 0, first_row: 0, last_row: 0, diagonal: [0; 4] }),
            near: C::ViewTable::filled(count, N::ZERO),
            stadiums: C::ViewTable::filled(count, None),
            #[cfg(feature = "acceleration-tables")]
            shadow: C::ViewTable::filled(count, ShadowBound::UNSET),
            #[cfg(feature = "acceleration-tables")]
            hierarchy: C::Hierarchy::filled(if C::HIERARCHY { REFERENCES_PER_OBJECT * count } else { 0 }, BvhNode::UNSET),
            #[cfg(feature = "acceleration-tables")]
            hierarchy_order: C::Hierarchy::filled(if C::HIERARCHY { REFERENCES_PER_OBJECT * count } else { 0 }, C::Index::default()),
            #[cfg(feature = "acceleration-tables")]
            hierarchy_nodes: 0,
            grid: Grid::inactive(count),
            shadow_tables: Unset::UNSET,
        }
    }

    /// The thesis's `preprocess` for the optimizations (digest §8.2).
    pub fn build(camera: &Camera<N>, optimizations: Optimizations, objects: &[ObjectDescription]) -> Self {
        Self::build_with(camera, optimizations, objects, Tuning::IMPROVED)
    }

    pub fn build_with(camera: &Camera<N>, optimizations: Optimizations, objects: &[ObjectDescription], tuning: Tuning) -> Self {
        let mut acceleration = Self::unset(objects.len());
        acceleration.rebuild(camera, optimizations, objects, tuning);
        acceleration
    }

    /// [`Acceleration::build_with`] in place, so that the structures in a `static` (the
    /// firmware's scene) are never copied through the stack.
    pub fn rebuild(&mut self, camera: &Camera<N>, optimizations: Optimizations, objects: &[ObjectDescription], tuning: Tuning) {
        let count = objects.len().min(self.order.slots().len()).min(C::Index::MAX);
        // The geometry as the tracer will see it: the inverse rounded to N, inverted back.
        let of = |index: usize| {
            let geometry = objects.get(index).and_then(rendered_geometry::<N>)?;
            Some((ObjectBounds::of_geometry(&geometry), Some(geometry)))
        };
        self.rebuild_with(camera, optimizations, tuning, count, of);
    }

    /// [`Acceleration::rebuild`] from each object's bounds made at build time in the number type
    /// (a baked scene's whose view moves): no `f64` at all. The same structures as
    /// `rebuild` for the same bounds, but that objects reaching the eye plane cover the whole
    /// screen (the eye-plane clip needs the `f64` silhouettes).
    pub fn rebuild_from_bounds(&mut self, camera: &Camera<N>, optimizations: Optimizations, bounds: &[ObjectBounds<N>]) {
        let count = bounds.len().min(self.order.slots().len()).min(C::Index::MAX);
        self.rebuild_with(camera, optimizations, Tuning::IMPROVED, count, |index| bounds.get(index).map(|b| (*b, None)));
    }

    /// What every build of the tables and every hold of baked tables sets first: the settings,
    /// the objects' count and the screen for `camera`, which it returns.
    fn settle(&mut self, camera: &Camera<N>, optimizations: Optimizations, tuning: Tuning, count: usize) -> Screen {
        self.screen = if SILHOUETTES { Screen::new(camera) } else { Screen::sized(camera.width(), camera.height()) };
        self.count = count;
        self.optimizations = optimizations;
        self.tuning = tuning;
        self.screen
    }

    /// The common part: `of(index)` gives an object's bounds and, on the host, its f64
    /// geometry (for the thesis's tuning and the eye-plane clip); `None`: nothing is known (a
    /// singular transform), the object covers the screen.
    fn rebuild_with(
        &mut self,
        camera: &Camera<N>,
        optimizations: Optimizations,
        tuning: Tuning,
        count: usize,
        of: impl Fn(usize) -> Option<(ObjectBounds<N>, Option<ObjectGeometry>)>,
    ) {
        let screen = self.settle(camera, optimizations, tuning, count);
        for (index, place) in self.order.slots_mut().iter_mut().enumerate() {
            *place = C::Index::new(index);
        }
        self.extents.slots_mut().fill(Extent::whole(&screen));
        self.near.slots_mut().fill(-N::MAX);
        self.stadiums.slots_mut().fill(None);
        #[cfg(feature = "acceleration-tables")]
        self.shadow.slots_mut().fill(ShadowBound::always());
        let corners = if SILHOUETTES { window_corners(&screen, camera) } else { [[0.0; 3]; 4] };
        let map = ScreenMap::new(camera);
        // Our tuning: capsules seen from the eye, in the number type (`capsule`); the thesis's:
        // its volumes projected in f64.
        // Without the `f64-silhouettes` feature (the firmware) there are only the capsules.
        let capsules = tuning.tight_silhouettes || !SILHOUETTES;
        // And each object's capsule for the grid's per-entry depth bounds (28 bytes in f32).
        let mut stored = C::PerObject::<Capsule<N>>::filled(count, Capsule::UNSET);
        let mut shapes = C::PerObject::<Primitive>::filled(count, Primitive::Sphere);
        for index in 0..count {
            let Some((bounds, geometry)) = of(index) else { continue };
            if let Some(shape) = shapes.slots_mut().get_mut(index) {
                *shape = bounds.primitive;
            }
            let capsule = if capsules { bounds.capsule } else { Capsule::UNSET };
            if let Some(slot) = stored.slots_mut().get_mut(index) {
                *slot = capsule;
            }
            // A capsule that reaches the eye plane covers the whole screen; its object's f64
            // silhouette clipped at the eye plane (`projection`, B16) does better. Only such
            // objects with their geometry take that path (the thesis scenes have none); from
            // bounds alone, every build does as the firmware does (so a host builds the chip's
            // grid exactly: `crate::bake`).
            let reaches_eye = SILHOUETTES && geometry.is_some() && capsules && map.cover(&capsule) == capsule::Covered::Whole && capsule.radius != N::MAX;
            // The f64 paths need the geometry: without it (bounds made at build time), the whole
            // screen and no depth bound.
            let silhouette = |tight: bool| match &geometry {
                Some(geometry) if SILHOUETTES => Extent::of(&screen, &screen.project_object(geometry, tight)),
                _ => Extent::whole(&screen),
            };
            // Pixelbuffer fills the extents' octagons (`render::fill_volumes`).
            if optimizations.extents || optimizations.grid || (optimizations.pixelbuffer && capsules) {
                self.extents.slots_mut()[index] = if reaches_eye {
                    silhouette(true)
                } else if capsules {
                    let (covered, stadium) = map.cover_and_stadium(&capsule);
                    if let Some(slot) = self.stadiums.slots_mut().get_mut(index) {
                        *slot = stadium;
                    }
                    Extent::of_cover(&map, &covered)
                } else {
                    silhouette(false)
                };
            }
            if optimizations.sortlist {
                if capsules && !reaches_eye {
                    if let Some(bound) = map.depth_bound(&capsule) {
                        self.near.slots_mut()[index] = bound;
                    }
                } else if let Some(bound) = geometry.as_ref().filter(|_| SILHOUETTES).and_then(|geometry| sortlist::depth_bound(&screen, &corners, geometry)) {
                    self.near.slots_mut()[index] = N::from_f64(bound);
                }
            }
            #[cfg(feature = "acceleration-tables")]
            if tuning.shadow_culling && optimizations.extents {
                self.shadow.slots_mut()[index] = bounds.shadow;
            }
        }
        #[cfg(feature = "acceleration-tables")]
        {
            self.hierarchy_nodes = 0;
            if C::HIERARCHY && tuning.shadow_culling && optimizations.extents && count > HIERARCHY_ABOVE {
                self.hierarchy_nodes = build_hierarchy::<C>(count, &of, self.hierarchy.slots_mut(), self.hierarchy_order.slots_mut());
            }
        }
        if optimizations.sortlist {
            let near = self.near.slots();
            if let Some(order) = self.order.slots_mut().get_mut(..count) {
                sortlist::sort_by_bound::<C, _>(order, |i| near.get(i).copied().unwrap_or(-N::MAX));
            }
        }
        if !optimizations.grid {
            self.grid.clear();
            return;
        }
        let capsules_of = |index: usize| stored.slots().get(index).copied();
        let polygon = |index: usize| match of(index).and_then(|(_, geometry)| geometry) {
            Some(geometry) if SILHOUETTES => screen.project_object(&geometry, tuning.tight_silhouettes),
            _ => projection::Projected::Whole,
        };
        let near = self.near.slots();
        let block_capsule = |index: usize, columns: (u16, u16), rows: (u16, u16)| -> N {
            let global = near.get(index).copied().unwrap_or(-N::MAX);
            // Only cylinders and cones gain: a sphere's or cube's capsule is a ball.
            let shaped = shapes.slots().get(index).is_some_and(|p| p.has_axis());
            let block = if shaped { capsules_of(index).and_then(|capsule| map.block_depth_bound(&capsule, columns, rows)) } else { None };
            match block {
                Some(bound) if bound > global => bound,
                _ => global,
            }
        };
        let block_depth = |index: usize, columns: (u16, u16), rows: (u16, u16)| -> N {
            let global = near.get(index).copied().unwrap_or(-N::MAX);
            let block = of(index)
                .and_then(|(_, geometry)| geometry)
                .filter(|_| SILHOUETTES)
                .and_then(|geometry| sortlist::block_depth_bound(&screen, &geometry, columns, rows));
            match block {
                Some(bound) if N::from_f64(bound) > global => N::from_f64(bound),
                _ => global,
            }
        };
        let depth: Option<&grid::BlockDepth<'_, N>> = match (optimizations.sortlist && tuning.cell_rectangles, capsules || !SILHOUETTES) {
            (false, _) => None,
            (true, false) => Some(&block_depth),
            (true, true) => Some(&block_capsule),
        };
        let cells = match (tuning.cell_rectangles, capsules || !SILHOUETTES) {
            (false, _) => grid::CellShape::Rectangles,
            (true, false) => grid::CellShape::Polygons,
            (true, true) => grid::CellShape::Octagons,
        };
        let (Some(order), Some(extents)) = (self.order.slots().get(..count), self.extents.slots().get(..count)) else { return };
        let stadiums = self.stadiums.slots();
        let stadium = |index: usize| stadiums.get(index).copied().flatten();
        self.grid.rebuild(&screen, order, extents, polygon, stadium, cells, depth);
    }

    /// Grid: its cells across and down, `None` without a grid.
    pub fn grid_side(&self) -> Option<u16> {
        self.grid.side()
    }

    /// Grid: the entries of the pixel's cell and the pixel's offsets in it; `None` without a grid.
    #[inline]
    pub fn grid_cell(&self, pixel: PixelPosition) -> Option<grid::CellAt<'_, C>> {
        self.grid.cell(pixel.column, pixel.row)
    }

    /// Holds the tables baked for the view and the lights the scene is prepared for (a baked
    /// scene's, in flash), in place of [`Acceleration::rebuild_from_bounds`]: each is read
    /// through the `Config`'s storage from now on (a view keeps the slice; storage of its own
    /// copies it; a grid, hierarchy or shadow table it cannot hold is left unused: the same
    /// picture, more tests). False when it cannot hold the per-object tables, which every
    /// render reads.
    #[must_use]
    pub fn hold_parts(&mut self, camera: &Camera<N>, optimizations: Optimizations, parts: &AccelerationParts<'static, N, C::Index>) -> bool {
        let count = parts.order.len().min(C::Index::MAX);
        self.settle(camera, optimizations, Tuning::IMPROVED, count);
        let held = [
            self.order.hold(parts.order),
            self.extents.hold(parts.extents),
            self.near.hold(parts.near),
            self.stadiums.hold(parts.stadiums),
            #[cfg(feature = "acceleration-tables")]
            self.shadow.hold(parts.shadow),
        ];
        if held.iter().any(|&slots| slots < count) {
            return false;
        }
        #[cfg(feature = "acceleration-tables")]
        {
            self.hierarchy_nodes = 0;
            if let Some(bvh) = parts.hierarchy {
                let nodes = self.hierarchy.hold(bvh.nodes);
                if nodes == bvh.nodes.len() && self.hierarchy_order.hold(bvh.order) == bvh.order.len() {
                    self.hierarchy_nodes = nodes;
                }
            }
        }
        self.grid.hold(parts.grid.filter(|_| optimizations.grid));
        if self.shadow_tables.hold(parts.shadow_tables) < parts.shadow_tables.len() {
            self.shadow_tables = Unset::UNSET;
        }
        true
    }

    /// The lights' shadow tables kept with the scene (empty: none; a render builds its own),
    /// one per light in the scene's order.
    #[inline]
    pub fn shadow_tables(&self) -> &[ShadowTables<'static, N>] {
        self.shadow_tables.slots()
    }

    /// The tables that depend on the view as built here, by their parts, with the lights'
    /// `shadow_tables`: what [`crate::bake`] writes into flash.
    pub fn parts<'a>(&'a self, shadow_tables: &'a [ShadowTables<'a, N>]) -> AccelerationParts<'a, N, C::Index> {
        let count = self.count;
        AccelerationParts {
            order: self.order.slots().get(..count).unwrap_or(&[]),
            extents: self.extents.slots().get(..count).unwrap_or(&[]),
            near: self.near.slots().get(..count).unwrap_or(&[]),
            stadiums: self.stadiums.slots().get(..count).unwrap_or(&[]),
            #[cfg(feature = "acceleration-tables")]
            shadow: self.shadow.slots().get(..count).unwrap_or(&[]),
            #[cfg(not(feature = "acceleration-tables"))]
            shadow: &[],
            grid: self.grid.parts(),
            #[cfg(feature = "acceleration-tables")]
            hierarchy: self.hierarchy(),
            #[cfg(not(feature = "acceleration-tables"))]
            hierarchy: None,
            shadow_tables,
        }
    }

    /// Every object, in test order (sorted by depth bound with Sortlist).
    #[inline]
    pub fn order(&self) -> &[C::Index] {
        self.order.slots().get(..self.count).unwrap_or(&[])
    }

    pub fn tuning(&self) -> Tuning {
        self.tuning
    }

    /// Whether the pixel lies in the rectangle of the object's extent (false when there is no
    /// extent): the hit cache's filter. The rectangle only, not the octagon's diagonals: the
    /// previous pixel's object is almost always still there, and the diagonal test cost
    /// more than the few intersections it saves (snooker, Cortex-M4F `f32`: 19 more
    /// ray–object tests, 63 K fewer instructions).
    #[inline]
    pub fn in_extent(&self, object: usize, pixel: PixelPosition) -> bool {
        self.extents.slots().get(object).is_some_and(|extent| extent.contains(pixel.column, pixel.row))
    }

    /// Sortlist is on (for the grid's per-entry bounds).
    #[inline]
    pub fn sorts(&self) -> bool {
        self.optimizations.sortlist && N::DEPTH_BOUNDS_HOLD
    }

    /// Whether primary rays try the previous hit object first.
    #[inline]
    pub fn uses_hit_cache(&self) -> bool {
        self.tuning.hit_cache && (self.optimizations.sortlist || self.optimizations.extents || self.optimizations.grid)
    }

    /// Whether shadow rays are culled (shadow culling tuned on, with Extents).
    #[inline]
    pub fn culls_shadows(&self) -> bool {
        cfg!(feature = "acceleration-tables") && self.tuning.shadow_culling && self.optimizations.extents && N::SHADOW_CULLING_HOLDS
    }

    /// Extents: whether the pixel lies outside the object's rectangle (skip it untested).
    #[inline]
    pub fn outside_extent(&self, object: usize, pixel: PixelPosition) -> bool {
        let tight = self.tuning.tight_silhouettes && (self.optimizations.extents || self.optimizations.grid);
        // Neither test asked for: no table read (the tables may be in flash, behind a check).
        if !self.optimizations.extents && !tight {
            return false;
        }
        let Some(extent) = self.extents.slots().get(object) else { return false };
        (self.optimizations.extents && !extent.contains(pixel.column, pixel.row))
            || (tight
                && (!extent.diagonals_contain(pixel.column, pixel.row, self.screen.height)
                    || self.stadiums.slots().get(object).copied().flatten().is_some_and(|stadium| !stadium.contains(pixel.column, pixel.row))))
    }

    /// Sortlist: whether every hit on `object` (and so on every later candidate) lies beyond
    /// the nearest hit so far, `t`. Strict, so an equal `t` is still tested.
    #[inline]
    pub fn beyond(&self, object: usize, t: N) -> bool {
        self.sorts() && self.near.slots().get(object).is_some_and(|near| *near > t)
    }

    /// The object's view from the light for the per-render shadow table (always meeting
    /// every shadow ray without the `acceleration-tables` feature).
    pub fn light_footprint(&self, object: usize, light: shadow_culling::LightPosition<N>) -> shadow_culling::LightFootprint<N> {
        #[cfg(feature = "acceleration-tables")]
        if let Some(bound) = self.shadow.slots().get(object) {
            return bound.footprint(light);
        }
        let _ = (object, light);
        shadow_culling::LightFootprint::always()
    }

    #[inline]
    pub fn may_shadow(&self, object: usize, point: Vector3<N>, direction: Vector3<N>, length: N) -> bool {
        #[cfg(feature = "acceleration-tables")]
        if let Some(bound) = self.shadow.slots().get(object) {
            return bound.may_block(point, direction, length);
        }
        let _ = (object, point, direction, length);
        true
    }

    pub fn screen(&self) -> &Screen {
        &self.screen
    }

    pub fn optimizations(&self) -> Optimizations {
        self.optimizations
    }

    /// Whether the grid is in use (on, and its pool did not overflow).
    pub fn grid_active(&self) -> bool {
        self.grid.is_active()
    }

    /// Entries over all grid cells.
    pub fn grid_entries(&self) -> usize {
        self.grid.entries()
    }

    /// The entries the grid's pool holds ([`Config::GRID_ENTRIES_PER_OBJECT`] per object; a
    /// baked grid holds exactly its entries).
    pub fn grid_capacity(&self) -> usize {
        self.grid.capacity()
    }

    /// Sortlist's lower bound of `t` for the object, as the render uses it (`None`: none known,
    /// or Sortlist off).
    pub fn near_bound(&self, object: usize) -> Option<N> {
        self.near.slots().get(object).copied().filter(|near| *near != -N::MAX)
    }

    /// The object's silhouette as a stadium, when it has one (our tuning).
    pub fn stadium(&self, object: usize) -> Option<capsule::Stadium> {
        self.stadiums.slots().get(object).copied().flatten()
    }

    pub fn extent(&self, object: usize) -> Option<Extent> {
        self.extents.slots().get(object).copied()
    }

    /// The shadow and secondary rays' hierarchy, when the scene has one (`Config::HIERARCHY`,
    /// or a baked one).
    #[cfg(feature = "acceleration-tables")]
    pub fn hierarchy(&self) -> Option<Bvh<'_, N, C::Index>> {
        let nodes = self.hierarchy.slots().get(..self.hierarchy_nodes).filter(|nodes| !nodes.is_empty())?;
        Some(Bvh { nodes, order: self.hierarchy_order.slots() })
    }
}

/// The hierarchy of the objects' world boxes, from each one's geometry as the tracer renders
/// it (its 8-vertex volume's box; a long triangle's cut into pieces, `early_split`): none (0
/// nodes) when an object has no geometry.
#[cfg(feature = "acceleration-tables")]
#[inline(never)]
fn build_hierarchy<C: Config>(
    count: usize,
    of: &impl Fn(usize) -> Option<(ObjectBounds<C::Number>, Option<ObjectGeometry>)>,
    nodes: &mut [BvhNode<C::Number>],
    order: &mut [C::Index],
) -> usize {
    let mut boxes = C::Hierarchy::<super::bvh::WorldBox>::filled(count, ([0.0; 3], [0.0; 3]));
    let mut triangles = C::Hierarchy::<Option<Triangle>>::filled(count, None);
    // As many references as the storage holds beyond the objects (`REFERENCES_PER_OBJECT`).
    let capacity = order.len().min(nodes.len());
    let mut references = C::Hierarchy::<super::bvh::WorldBox>::filled(capacity, ([0.0; 3], [0.0; 3]));
    let mut owners = C::Hierarchy::<usize>::filled(capacity, 0);
    let scratch = HierarchyScratch { boxes: boxes.slots_mut(), triangles: triangles.slots_mut(), references: references.slots_mut(), owners: owners.slots_mut() };
    build_hierarchy_in(count, &|index| of(index).and_then(|(_, geometry)| geometry), scratch, nodes, order).0
}

/// A triangle's corners in world space (`early_split` cuts its box along them).
#[cfg(feature = "acceleration-tables")]
type Triangle = [[f64; 3]; 3];

/// The hierarchy's working tables while it is built, in the caller's storage: a box and a
/// triangle per object, and a box and an owner per reference (as many as the nodes).
#[cfg(feature = "acceleration-tables")]
#[derive(Debug)]
pub struct HierarchyScratch<'a> {
    pub boxes: &'a mut [super::bvh::WorldBox],
    pub triangles: &'a mut [Option<Triangle>],
    pub references: &'a mut [super::bvh::WorldBox],
    pub owners: &'a mut [usize],
}

/// The hierarchy a baked scene of `objects` gets (none for [`BAKED_HIERARCHY_ABOVE`]
/// objects or fewer), built from the geometry the tracer renders in `N`, as a host's
/// preparation builds it: what [`crate::bake`] writes into flash (the chip
/// has no `f64` to build one). `nodes` and `order` as long as the references
/// ([`hierarchy_references`]); the hierarchy is the parts of them it used.
#[cfg(feature = "acceleration-tables")]
pub fn baked_hierarchy<'a, N: Number, I: Index>(objects: &[ObjectDescription], scratch: HierarchyScratch<'_>, nodes: &'a mut [BvhNode<N>], order: &'a mut [I]) -> Option<Bvh<'a, N, I>> {
    if objects.len() <= BAKED_HIERARCHY_ABOVE {
        return None;
    }
    let (used, references) = build_hierarchy_in(objects.len(), &|index| objects.get(index).and_then(rendered_geometry::<N>), scratch, nodes, order);
    let nodes = nodes.get(..used).filter(|nodes| !nodes.is_empty())?;
    Some(Bvh { nodes, order: order.get(..references)? })
}

/// The references a hierarchy of `objects` objects may take (its nodes and its order).
#[cfg(feature = "acceleration-tables")]
pub const fn hierarchy_references(objects: usize) -> usize {
    REFERENCES_PER_OBJECT * objects
}

#[cfg(feature = "acceleration-tables")]
fn build_hierarchy_in<N: Number, I: Index>(
    count: usize,
    geometry_of: &impl Fn(usize) -> Option<ObjectGeometry>,
    scratch: HierarchyScratch<'_>,
    nodes: &mut [BvhNode<N>],
    order: &mut [I],
) -> (usize, usize) {
    let HierarchyScratch { boxes, triangles, references, owners } = scratch;
    let (Some(boxes), Some(triangles)) = (boxes.get_mut(..count), triangles.get_mut(..count)) else { return (0, 0) };
    for (index, (slot, triangle)) in boxes.iter_mut().zip(triangles.iter_mut()).enumerate() {
        let Some(geometry) = geometry_of(index) else { return (0, 0) };
        let (low, high) = geometry.world_box();
        if !(low.iter().chain(&high).all(|c| c.is_finite())) {
            return (0, 0);
        }
        *slot = (low, high);
        *triangle = geometry.triangle();
    }
    // As many references as every table holds.
    let capacity = order.len().min(nodes.len()).min(references.len()).min(owners.len());
    let (Some(references), Some(owners)) = (references.get_mut(..capacity), owners.get_mut(..capacity)) else { return (0, 0) };
    let used = super::early_split::split(count, &|index| boxes.get(index).copied().unwrap_or_default(), &|index| triangles.get(index).copied().flatten(), references, owners);
    let Some(references) = references.get(..used) else { return (0, 0) };
    (super::bvh::build(references, |reference| owners.get(reference).copied().unwrap_or(0), nodes, order), used)
}

/// What the optimizations need of an object that depends on it alone: its primitive, its
/// bounding capsule for the screen and its shadow capsule, in the number type. Prepared at
/// preparation on the host, at build time for the firmware (`write_literal`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjectBounds<N> {
    pub primitive: Primitive,
    pub capsule: Capsule<N>,
    pub shadow: ShadowBound<N>,
}

impl<N: Number> ObjectBounds<N> {
    /// From the geometry the tracer renders (f64).
    pub fn of_geometry(geometry: &ObjectGeometry) -> Self {
        let (start, end, radius) = geometry.bounding_capsule();
        Self { primitive: geometry.primitive, capsule: Capsule::new(start, end, radius), shadow: ShadowBound::new(start, end, radius) }
    }

    /// For each object of the descriptions (`None` for a singular transform).
    pub fn of(description: &ObjectDescription) -> Option<Self> {
        rendered_geometry::<N>(description).map(|geometry| Self::of_geometry(&geometry))
    }

    /// [`ObjectBounds::of`], or no bounds at all (the object tested everywhere) for a singular
    /// transform: what [`crate::bake`] writes.
    pub fn or_everywhere(description: &ObjectDescription) -> Self {
        Self::of(description).unwrap_or(Self { primitive: description.primitive, capsule: Capsule::UNSET, shadow: ShadowBound::always() })
    }
}

/// The object's geometry as the tracer will see it: the inverse rounded to `N`, inverted back.
fn rendered_geometry<N: Number>(description: &ObjectDescription) -> Option<ObjectGeometry> {
    let inverse = description.world_from_object.affine_inverse()?;
    ObjectGeometry::new(description.primitive, &AffineTransform::<N>::from_matrix(&inverse))
}

/// The view-plane window's corners in world space (the parallel rays' extreme origins), as
/// Sortlist's [`sortlist::depth_bound`] takes them.
pub fn window_corners<N: Number>(screen: &Screen, camera: &Camera<N>) -> [[f64; 3]; 4] {
    let (w, h) = (screen.width - 1, screen.height - 1);
    [(0, 0), (w, 0), (0, h), (w, h)].map(|(c, r)| camera.view_plane_point(camera.pixel(c, r)).to_f64())
}
