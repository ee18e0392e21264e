//! The build's parameters in one type: the number type, where the objects live, and every
//! capacity the tracer's tables and stacks are sized by (the objects, the grid's pool, the
//! ray tree's depth, the antialiasing row). A signature names one generic, `C: Config`, not
//! eight.
//!
//! Stable Rust cannot size an array by a trait's constant in generic code, so the storage is
//! named by the trait's associated types instead: [`Arrays`] sets them to arrays and
//! `heapless::Vec`s of capacities in its own const parameters (the firmware's scene, a
//! `static` sized by its scene; the tests' and the host's), and a host build may set them to
//! storage sized at run time. The core reads them only as slices ([`Table`]) and lists
//! ([`List`]), so it never allocates.

use core::fmt::Debug;
use core::marker::PhantomData;

use crate::model::{Object, Objects, Palette, PreparedSolidNode, MAX_DEPTH, MAX_HELD_SPANS, MAX_LIGHTS, MAX_SOLID_NODES, MAX_SOLID_STACK, MAX_SPANS};
use crate::number::Number;
use crate::storage::{Index, List, Table, Unset};

/// The build's number type, object storage and capacities.
///
/// Every table is a storage type: an array or a list sized here ([`Arrays`]), the heap on a
/// host, or a table baked into flash ([`InFlash`](crate::storage::InFlash): the scene's own
/// `Config` that [`crate::bake`] writes). The tables a scene keeps are [`Unset`] (every byte zero
/// before preparation).
pub trait Config: 'static {
    /// The number type the tracer computes in.
    type Number: Number;
    /// An object's number in the tables (and a place in the grid's pool).
    type Index: Index;
    /// Where the prepared objects live (the scene's own list, or a baked scene's in flash).
    type Objects: Objects<Self::Number> + Unset;
    /// Where the solids' prepared nodes live (the scene's own list, or a baked scene's in flash,
    /// exactly its scene's), and the capacities of a ray's walk through them.
    type Solids: SolidStorage<Self::Number> + Unset;
    /// Where the scene's look-up table lives (the scene's own copy, or a baked scene's in flash).
    type Palette: PaletteStorage + Unset;
    /// One `T` per object: the scratch tables of preparation and of a render.
    type PerObject<T: Copy>: Table<T>;
    /// One per object of a table that depends on the view (each object's eye, extent, stadium,
    /// depth bound, shadow capsule, the test order): as [`Config::PerObject`], or in flash for a
    /// baked scene, whose view is fixed when it is baked.
    type ViewTable<T: Copy + Unset + 'static>: Table<T> + Unset;
    /// One `T` per object for each light after the first (as many tables of one per object as
    /// [`Config::OtherLights`] holds lights, one after the other): the per-render shadow tables
    /// of the other lights.
    type PerObjectPerOtherLight<T: Copy>: Table<T>;
    /// The lights after the first: a baked scene's exactly its scene's, a host's the format's
    /// [`MAX_LIGHTS`]` − 1`.
    type OtherLights<T: Clone>: List<T> + Unset;
    /// At most one `T` per object.
    type PerObjectList<T: Clone>: List<T> + Unset;
    /// The screen grid's pool: [`Config::GRID_ENTRIES_PER_OBJECT`] `T`s per object (or a baked
    /// scene's grid, in flash).
    type GridPool<T: Copy + Unset + 'static>: Table<T> + Unset;
    /// The secondary rays' space grid's entries: `ENTRIES_PER_OBJECT` per object.
    type SpaceEntries: Table<Self::Index> + Unset;
    /// The per-render lists of each object's blockers from the 128th object on, and where each
    /// object's list starts (kept when [`Config::BLOCKER_LISTS`]).
    type BlockerLists: Table<Self::Index>;
    /// The shadow rays' hierarchy of boxes (`optimize::bvh`): its nodes, and the objects its
    /// leaves hold, one `T` per object each (built when [`Config::HIERARCHY`], or a baked
    /// scene's, in flash; none: the walk is not linked).
    type Hierarchy<T: Copy + Unset + 'static>: Table<T> + Unset;
    /// The screen grid's cells (and one more): [`GRID_SIZE`](crate::optimize::grid::GRID_SIZE)
    /// squared on an array, up to [`MAX_GRID_SIZE`](crate::optimize::grid::MAX_GRID_SIZE)
    /// squared sized at run time (the grid's side then grows with the objects).
    type ScreenCells<T: Copy + Unset + 'static>: Table<T> + Unset;
    /// The lights' shadow tables kept with the scene, one `T` per light
    /// (`optimize::shadow_culling::ShadowTables`): none where each render builds its own (on the
    /// stack), a baked scene's in flash (the render then builds none, and the code that builds
    /// them is not linked).
    type LightTables<T: Copy + Unset + 'static>: Table<T> + Unset;
    /// The ray tree's stack of nodes: at most [`Config::TREE_DEPTH`].
    type TreeStack<T: Clone>: List<T>;
    /// One row of antialiasing corners: its length is how many the render keeps (the
    /// image's width plus one shares every corner; fewer traces some twice).
    type CornerRow: Table<[u8; 3]>;
    /// The most objects the tables hold.
    const MAX_OBJECTS: usize;
    /// The grid's pool entries per object (zero: no grid built here).
    const GRID_ENTRIES_PER_OBJECT: usize;
    /// The deepest ray tree the render follows (a scene's deeper `depth` is cut here).
    const TREE_DEPTH: usize;
    /// Whether a render lists each object's possible blockers beyond the first 128 (the
    /// blocker sets' capacity), so that a shadow ray tests those instead of every object from
    /// the 128th on: for scenes of thousands of objects, on a host (`render/shadow_tables.rs`).
    const BLOCKER_LISTS: bool = false;
    /// Whether a scene of more than 128 objects gets a hierarchy of boxes for its shadow rays
    /// (`optimize::bvh`), in place of the blocker tables, whose work grows with the pairs of
    /// objects: a host's, for scenes of thousands of objects (Haines' SPD).
    const HIERARCHY: bool = false;

    /// The grid's pool entries for a scene of `objects` objects (a table sized at run time is
    /// made this long; an array keeps its length).
    fn grid_entries(objects: usize) -> usize {
        objects.saturating_mul(Self::GRID_ENTRIES_PER_OBJECT)
    }
}

/// Where a build keeps its solids' prepared nodes, and the capacities of the lists a ray's walk
/// through a solid holds (`csg::solid`), in the type: the firmware's are exactly what its
/// scene's solids need (`model::SolidNeeds`, which preparation derives from each tree: spans
/// of `A op B` ≤ spans of `A` + spans of `B`), a host's the format's limits. Each list lives
/// on the stack for one ray.
pub trait SolidStorage<N>: core::ops::Deref<Target = [PreparedSolidNode<N>]> + Default {
    /// The spans the walk's lists hold together ([`MAX_HELD_SPANS`] at most).
    type HeldSpans<T: Clone>: List<T>;
    /// The spans of one list, an operation's result ([`MAX_SPANS`] at most).
    type Spans<T: Clone>: List<T>;
    /// The lists held at once ([`MAX_SOLID_STACK`] at most).
    type Lists<T: Clone>: List<T>;
}

/// Where a build keeps the scene's look-up table: the scene's own copy ([`OwnedPalette`], a
/// host's and the tests'), or the firmware's in flash, written at build time from the same
/// scene (it then takes none of the chip's RAM: 768 bytes).
pub trait PaletteStorage: core::ops::Deref<Target = Palette> + Default {
    /// Holds `palette` from now on. A table in flash already holds it (written from the same
    /// scene) and keeps it.
    fn hold(&mut self, palette: &Palette);
}

/// A look-up table of the scene's own (every entry black until preparation holds the scene's).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OwnedPalette(pub Palette);

impl Default for OwnedPalette {
    fn default() -> Self {
        Self::BLACK
    }
}

impl OwnedPalette {
    /// Every entry black: the value of a scene not yet prepared.
    pub const BLACK: Self = Self(Palette { entries: [crate::model::Rgb4 { r: 0, g: 0, b: 0 }; 256] });
}

impl Unset for OwnedPalette {
    const UNSET: Self = Self::BLACK;
}

impl core::ops::Deref for OwnedPalette {
    type Target = Palette;

    #[inline(always)]
    fn deref(&self) -> &Palette {
        &self.0
    }
}

impl PaletteStorage for OwnedPalette {
    fn hold(&mut self, palette: &Palette) {
        self.0 = *palette;
    }
}

/// The scene's own list of nodes, walked with the format's limits.
impl<N, const K: usize> SolidStorage<N> for heapless::Vec<PreparedSolidNode<N>, K> {
    type HeldSpans<T: Clone> = heapless::Vec<T, MAX_HELD_SPANS>;
    type Spans<T: Clone> = heapless::Vec<T, MAX_SPANS>;
    type Lists<T: Clone> = heapless::Vec<T, MAX_SOLID_STACK>;
}

/// The grid's pool entries per object by default: an object may overlap this many cells on
/// average (24); none without the `acceleration-tables` feature (no grid).
pub const DEFAULT_GRID_ENTRIES_PER_OBJECT: usize = if cfg!(feature = "acceleration-tables") { 24 } else { 0 };

/// The screen grid's cells on an array: the thesis's 20x20 (`optimize::grid::GRID_SIZE`), none
/// without the `acceleration-tables` feature (the grid is then inactive).
pub const SCREEN_GRID_CELLS: usize = if cfg!(feature = "acceleration-tables") { 20 * 20 } else { 0 };

/// The ray tree's depth by default: the format's deepest.
pub const DEFAULT_TREE_DEPTH: usize = MAX_DEPTH as usize;

/// The antialiasing row by default: an image up to 2,048 pixels wide shares every corner (6 KB
/// of stack); a wider one traces the corners beyond again.
pub const DEFAULT_ANTIALIAS_ROW: usize = 2049;

/// Every table an array of a capacity fixed at compile time, in RAM: `K` objects, `POOL` grid
/// entries per object, a ray tree `DEPTH` deep, antialiasing rows of `ROW` corners and
/// `OTHER_LIGHTS` lights after the first; the objects, the solids' nodes and the look-up table
/// the scene's own (`heapless::Vec`s, [`OwnedPalette`]). The tests' scenes are one, and a board
/// that prepares its scene on the chip; a baked scene has a `Config` of its own
/// ([`crate::bake`]).
pub struct Arrays<
    N,
    const K: usize,
    const POOL: usize = DEFAULT_GRID_ENTRIES_PER_OBJECT,
    const DEPTH: usize = DEFAULT_TREE_DEPTH,
    const ROW: usize = DEFAULT_ANTIALIAS_ROW,
    const OTHER_LIGHTS: usize = { MAX_LIGHTS - 1 },
>(PhantomData<N>);

impl<N, const K: usize, const POOL: usize, const DEPTH: usize, const ROW: usize, const OTHER_LIGHTS: usize> Debug for Arrays<N, K, POOL, DEPTH, ROW, OTHER_LIGHTS> {
    fn fmt(&self, formatter: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(formatter, "Arrays<{K} objects, {POOL} grid entries each, depth {DEPTH}, row {ROW}>")
    }
}

impl<N: Number + 'static, const K: usize, const POOL: usize, const DEPTH: usize, const ROW: usize, const OTHER_LIGHTS: usize> Config for Arrays<N, K, POOL, DEPTH, ROW, OTHER_LIGHTS> {
    type Number = N;
    type Index = u16;
    type Objects = heapless::Vec<Object<N>, K>;
    type Solids = heapless::Vec<PreparedSolidNode<N>, MAX_SOLID_NODES>;
    type Palette = OwnedPalette;
    type PerObject<T: Copy> = [T; K];
    type ViewTable<T: Copy + Unset + 'static> = [T; K];
    type PerObjectPerOtherLight<T: Copy> = [[T; K]; OTHER_LIGHTS];
    type OtherLights<T: Clone> = heapless::Vec<T, OTHER_LIGHTS>;
    type PerObjectList<T: Clone> = heapless::Vec<T, K>;
    type GridPool<T: Copy + Unset + 'static> = [[T; POOL]; K];
    type SpaceEntries = [[u16; SPACE_ENTRIES_PER_OBJECT]; K];
    type BlockerLists = [u16; 0];
    type Hierarchy<T: Copy + Unset + 'static> = [T; 0];
    type ScreenCells<T: Copy + Unset + 'static> = [T; SCREEN_GRID_CELLS + 1];
    type LightTables<T: Copy + Unset + 'static> = [T; 0];
    type TreeStack<T: Clone> = heapless::Vec<T, DEPTH>;
    type CornerRow = [[u8; 3]; ROW];
    const MAX_OBJECTS: usize = K;
    const GRID_ENTRIES_PER_OBJECT: usize = POOL;
    const TREE_DEPTH: usize = DEPTH;
}

/// The space grid's cell entries per object on average at most (else no grid).
pub const SPACE_ENTRIES_PER_OBJECT: usize = 8;
