//! Grid (§4.7.4, `makegrid`): the screen cut into 20x20 cells, each with the objects that may
//! cover it, in test order (so with Sortlist each cell list stays sorted).
//!
//! No heap: the cell lists share one pool of `Config::GRID_ENTRIES_PER_OBJECT` entries an object
//! (an object's number and two `u16`s), with a start offset per cell and one more
//! (`Config::ScreenCells`). The cell size is the thesis's `(pixels − 1)/20 + 1`.
//!
//! The adaptive grid the thesis proposes (§5.2.1): where the storage is sized at run time, a
//! scene of many objects gets more cells, √(objects/2) across up to [`MAX_GRID_SIZE`] (a scene
//! of thousands of triangles fills a 20x20 cell's list with objects that miss most of its
//! pixels). Should the pool overflow with more cells, the thesis's 20 are tried.
//! A cell list simply ends at the next cell's start (the thesis's NULL-dereferencing
//! `nextobject`, digest B4, cannot happen). Should a scene need more entries than the pool
//! holds, the grid is switched off for that scene (every object is a candidate), which changes
//! speed, never the image.
//!
//! Thesis-faithful membership: an object is in every cell its extent rectangle overlaps. With
//! `cell_rectangles` (our default), membership uses the object's silhouette polygon, and each
//! entry also keeps the polygon's bounding rectangle *within that cell* (offsets from the
//! cell's corner, one byte each, saturating at 255, which only ever widens it), so a thin
//! oblique object skips most pixels of the cells it crosses.

use core::num::NonZeroU16;

use super::capsule::Stadium;
use super::extents::Extent;
use crate::config::Config;
use crate::storage::{Index, Table, Unset};
use crate::number::Number;
use super::pixelbuffer::band_span;
use super::projection::{Projected, Screen};
use super::sortlist::{heapsort, INSERTION_SORT_BELOW};

/// Cells across and down (`GRIDCOL`, `GRIDROW`).
pub const GRID_SIZE: u16 = 20;
/// The most cells across and down of a grid whose storage is sized at run time.
pub const MAX_GRID_SIZE: u16 = 64;
/// No cells at all without the `acceleration-tables` feature (the grid is then inactive): an
/// array's cells, `Config::ScreenCells`.
pub const CELLS: usize = crate::config::SCREEN_GRID_CELLS;
const _: () = assert!(CELLS == 0 || CELLS == GRID_SIZE as usize * GRID_SIZE as usize);
/// [`MAX_GRID_SIZE`]'s cells.
const MAX_CELLS: usize = if super::build_options::TABLES { MAX_GRID_SIZE as usize * MAX_GRID_SIZE as usize } else { 0 };
/// What an entry knows of its object within the cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CellShape {
    /// The whole cell (the thesis: membership by extent rectangle).
    Rectangles,
    /// The bounding rectangle of the silhouette polygon within the cell.
    Polygons,
    /// The bounding rectangle of the extent octagon within the cell, narrowed by the
    /// object's [`Stadium`] where it has one (integer arithmetic).
    Octagons,
}

/// A per-entry depth bound: (object, columns, rows) -> lower bound of `t`.
pub type BlockDepth<'a, N> = dyn Fn(usize, (u16, u16), (u16, u16)) -> N + 'a;

/// One cell entry: the object's number, then the columns and rows it may cover within the cell
/// as `first | last << 8` offsets from the cell's corner.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Entry<I> {
    pub object: I,
    pub columns: u16,
    pub rows: u16,
}

impl<I: crate::storage::Unset> crate::storage::Unset for Entry<I> {
    const UNSET: Self = Self { object: I::UNSET, columns: 0, rows: 0 };
}

/// A pixel's cell: its entries, their depth bounds, and the pixel's offsets from the cell's
/// corner (saturated at 255).
pub type CellAt<'a, C> = (&'a [Entry<<C as Config>::Index>], &'a [<C as Config>::Number], u16, u16);

const WHOLE_CELL: u16 = 0xFF00;

/// A cell's width and height in pixels (at least 1, so dividing by them cannot fail).
#[derive(Clone, Copy, Debug)]
struct CellSize {
    width: NonZeroU16,
    height: NonZeroU16,
}

pub struct Grid<C: Config> {
    /// The cells' size; `None` when the grid is off or its pool overflowed (and, all bytes
    /// zero, before it is built).
    cells: Option<CellSize>,
    /// Cells across and down (0 until built: every byte of an unset grid is zero).
    side: u16,
    starts: C::ScreenCells<C::Index>,
    pool: C::GridPool<Entry<C::Index>>,
    /// With Sortlist: each entry's lower bound of `t` for the part of its object seen through
    /// the entry's rectangle (cell lists are sorted by it).
    depth: C::GridPool<C::Number>,
}

impl<C: Config> core::fmt::Debug for Grid<C> {
    fn fmt(&self, formatter: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        formatter.debug_struct("Grid").field("cells", &self.cells).field("entries", &self.entries()).field("capacity", &self.pool.slots().len()).finish()
    }
}

impl<C: Config> Clone for Grid<C> {
    fn clone(&self) -> Self {
        Self { cells: self.cells, side: self.side, starts: self.starts.clone(), pool: self.pool.clone(), depth: self.depth.clone() }
    }
}

impl<C: Config> Grid<C> {
    /// Every byte zero, inactive: the value before [`Grid::rebuild`] (a `static` holding it
    /// costs zero-initialised RAM and no flash).
    pub const UNSET: Self = Self { cells: None, side: 0, starts: Unset::UNSET, pool: Unset::UNSET, depth: Unset::UNSET };
}

impl<N: Number, C: Config<Number = N>> Grid<C> {
    /// An inactive grid whose pool holds [`Config::grid_entries`] for `objects` objects.
    pub fn inactive(objects: usize) -> Self {
        let entries = C::grid_entries(objects);
        Self { cells: None, side: 0, starts: C::ScreenCells::filled(MAX_CELLS + 1, C::Index::default()), pool: C::GridPool::filled(entries, Entry::default()), depth: C::GridPool::filled(entries, -N::MAX) }
    }

    /// The entries the pool holds.
    pub fn capacity(&self) -> usize {
        self.pool.slots().len()
    }

    /// `order`: the objects in test order; `extents` indexed by object number; `polygon` gives
    /// an object's silhouette (used only with `cell_rectangles`).
    pub fn build(
        screen: &Screen,
        order: &[C::Index],
        extents: &[Extent],
        polygon: impl Fn(usize) -> Projected,
        cells: CellShape,
        depth: Option<&BlockDepth<'_, N>>,
    ) -> Self {
        let mut grid = Self::inactive(order.len());
        grid.rebuild(screen, order, extents, polygon, |_| None, cells, depth);
        grid
    }

    /// [`Grid::build`] in place, so that a grid in a `static` (the firmware's) is never copied
    /// through the stack.
    #[allow(clippy::too_many_arguments, reason = "the grid's inputs, kept as they are while the optimizations are being reworked elsewhere")]
    pub fn rebuild(
        &mut self,
        screen: &Screen,
        order: &[C::Index],
        extents: &[Extent],
        polygon: impl Fn(usize) -> Projected,
        stadium: impl Fn(usize) -> Option<Stadium>,
        cells: CellShape,
        depth: Option<&BlockDepth<'_, N>>,
    ) {
        // The pool and the bounds are not cleared: the pass below writes every entry a cell
        // list reaches (clearing them cost the lattice 7 k instructions a frame on the Cortex-M4F).
        self.cells = None;
        self.starts.slots_mut().fill(C::Index::default());
        if C::GRID_ENTRIES_PER_OBJECT == 0 {
            return;
        }
        // As many cells across as the storage holds up to √(objects/2), at least the thesis's.
        // (Integers: no f64 on the firmware, whose array holds 20 across.)
        let room = self.starts.slots().len().saturating_sub(1);
        let squared = |side: u16| usize::from(side) * usize::from(side);
        let wanted = (GRID_SIZE..=MAX_GRID_SIZE).rev().find(|side| squared(*side) <= room && 2 * squared(*side) <= order.len()).unwrap_or(GRID_SIZE);
        if !self.fill(wanted, screen, order, extents, &polygon, &stadium, cells, depth) && (wanted == GRID_SIZE || !self.fill(GRID_SIZE, screen, order, extents, &polygon, &stadium, cells, depth)) {
            self.clear();
        }
    }

    /// [`Grid::rebuild`] with `side` cells across and down: false when the pool overflows.
    #[allow(clippy::too_many_arguments)]
    fn fill(
        &mut self,
        side: u16,
        screen: &Screen,
        order: &[C::Index],
        extents: &[Extent],
        polygon: &impl Fn(usize) -> Projected,
        stadium: &impl Fn(usize) -> Option<Stadium>,
        cells: CellShape,
        depth: Option<&BlockDepth<'_, N>>,
    ) -> bool {
        if usize::from(side) * usize::from(side) + 1 > self.starts.slots().len() {
            return false;
        }
        self.side = side;
        let grid = self;
        // At least 1, so the divisions below cannot be by zero.
        let (cell_width, cell_height) = (screen.width.saturating_sub(1) / side + 1, screen.height.saturating_sub(1) / side + 1);
        let (cell_width, cell_height) = (NonZeroU16::new(cell_width).unwrap_or(NonZeroU16::MIN), NonZeroU16::new(cell_height).unwrap_or(NonZeroU16::MIN));
        // Calls `add(cell, entry)` for every cell the object may cover.
        let visit = |object: usize, add: &mut dyn FnMut(usize, Entry<C::Index>)| {
            let Some(extent) = extents.get(object).copied() else { return };
            if extent.is_empty() {
                return;
            }
            let shape = if cells == CellShape::Polygons && super::build_options::SILHOUETTES { polygon(object) } else { Projected::Whole };
            let stadium = if cells == CellShape::Octagons { stadium(object) } else { None };
            let (width, height) = (cell_width.get(), cell_height.get());
            for cell_row in extent.first_row / cell_height..=(extent.last_row / cell_height).min(side - 1) {
                let y0 = cell_row * height;
                let rows = (y0.max(extent.first_row), (y0 + (height - 1)).min(extent.last_row));
                for cell_column in extent.first_column / cell_width..=(extent.last_column / cell_width).min(side - 1) {
                    let x0 = cell_column * width;
                    let columns = (x0.max(extent.first_column), (x0 + (width - 1)).min(extent.last_column));
                    let cell = usize::from(cell_row) * usize::from(side) + usize::from(cell_column);
                    let pack = |first: u16, last: u16, origin: u16| (first - origin).min(255) | ((last - origin).min(255) << 8);
                    if cells == CellShape::Octagons {
                        // The octagon's rows within the cell's columns, and its columns there.
                        let mut covered: Option<(u16, u16, u16, u16)> = None;
                        for row in rows.0..=rows.1 {
                            let Some((first, last)) = extent.row_span(row, screen.height) else { continue };
                            let (first, last) = (first.max(columns.0), last.min(columns.1));
                            if first > last {
                                continue;
                            }
                            covered = Some(match covered {
                                None => (first, last, row, row),
                                Some((c1, c2, r1, _)) => (c1.min(first), c2.max(last), r1, row),
                            });
                        }
                        let Some((c1, c2, r1, r2)) = covered else { continue };
                        // And within the stadium's part of the cell, for thin oblique objects.
                        let ((c1, c2), (r1, r2)) = match stadium {
                            Some(stadium) => match stadium.block((c1, c2), (r1, r2)) {
                                Some(rectangle) => rectangle,
                                None => continue,
                            },
                            None => ((c1, c2), (r1, r2)),
                        };
                        add(cell, Entry { object: C::Index::new(object), columns: pack(c1, c2, x0), rows: pack(r1, r2, y0) });
                        continue;
                    }
                    let Projected::Points(p) = &shape else {
                        add(cell, Entry { object: C::Index::new(object), columns: WHOLE_CELL, rows: WHOLE_CELL });
                        continue;
                    };
                    // The polygon's columns within the cell's rows, then its rows within those
                    // columns.
                    let Some((c1, c2)) = band_span(p, 1, f64::from(rows.0), f64::from(rows.1), screen.width) else { continue };
                    let (c1, c2) = (c1.max(columns.0), c2.min(columns.1));
                    if c1 > c2 {
                        continue;
                    }
                    let Some((r1, r2)) = band_span(p, 0, f64::from(c1), f64::from(c2), screen.height) else { continue };
                    let (r1, r2) = (r1.max(rows.0), r2.min(rows.1));
                    if r1 > r2 {
                        continue;
                    }
                    add(cell, Entry { object: C::Index::new(object), columns: pack(c1, c2, x0), rows: pack(r1, r2, y0) });
                }
            }
        };
        // One visit: the entries in test order into the pool, each one's cell noted and its
        // depth bound computed; then a stable counting sort by cell, in place. (Visiting twice,
        // to count and then to place, cost the lattice a third of its preparation.)
        let capacity = grid.pool.slots().len().min(C::Index::MAX);
        let pool = grid.pool.slots_mut();
        let bounds = grid.depth.slots_mut();
        // Each entry's cell, then its place in the sorted pool.
        let mut places = C::GridPool::<C::Index>::filled(capacity, C::Index::default());
        let places = places.slots_mut();
        // Entries per cell, then each cell's next free place.
        let cells_used = usize::from(side) * usize::from(side);
        let mut next = C::ScreenCells::<C::Index>::filled(cells_used, C::Index::default());
        let next = next.slots_mut().get_mut(..cells_used).unwrap_or(&mut []);
        let mut used = 0usize;
        let mut overflowed = false;
        for &object in order {
            let object = object.get();
            visit(object, &mut |cell, entry| {
                let (Some(place), Some(slot), Some(count)) = (places.get_mut(used), pool.get_mut(used), next.get_mut(cell)) else {
                    overflowed = true;
                    return;
                };
                *place = C::Index::new(cell);
                *slot = entry;
                // At most `capacity` entries in all (a place for each), so no cell wraps.
                *count = C::Index::new(count.get() + 1);
                if let (None, Some(bound)) = (depth, bounds.get_mut(used)) {
                    *bound = -N::MAX;
                }
                if let (Some(depth), Some(bound)) = (depth, bounds.get_mut(used)) {
                    let origin = |packed: u16, size: u16, index: u16| {
                        let corner = index * size;
                        (corner + (packed & 0xFF), corner + (packed >> 8))
                    };
                    let (cell_row, cell_column) = ((cell / usize::from(side)) as u16, (cell % usize::from(side)) as u16);
                    let columns = origin(entry.columns, cell_width.get(), cell_column);
                    let rows = origin(entry.rows, cell_height.get(), cell_row);
                    *bound = depth(object, columns, rows);
                }
                used += 1;
            });
        }
        if overflowed || used > capacity {
            return false;
        }
        let mut total = 0;
        let starts = grid.starts.slots_mut().get_mut(..=cells_used).unwrap_or(&mut []);
        for (start, count) in starts.iter_mut().zip(next.iter_mut()) {
            *start = C::Index::new(total);
            total += count.get();
            *count = *start;
        }
        if let Some(end) = starts.last_mut() {
            *end = C::Index::new(total);
        }
        // Each entry's place: its cell's next (stable: entries of a cell keep test order).
        for place in places.iter_mut().take(used) {
            if let Some(next) = next.get_mut(place.get()) {
                *place = *next;
                *next = C::Index::new(next.get() + 1);
            }
        }
        // Move every entry to its place by following the permutation's cycles.
        for index in 0..used {
            while let Some(&target) = places.get(index) {
                let target = target.get();
                if target == index || target >= used {
                    break;
                }
                pool.swap(index, target);
                bounds.swap(index, target);
                places.swap(index, target);
            }
        }
        // Sort each cell by its entries' bounds, ties in test order (the order they are in).
        if depth.is_some() {
            for span in starts.windows(2) {
                let &[start, end] = span else { continue };
                let range = start.get()..end.get();
                let (Some(bounds), Some(pool), Some(places)) = (bounds.get_mut(range.clone()), pool.get_mut(range.clone()), places.get_mut(range)) else { continue };
                if C::MAX_OBJECTS < INSERTION_SORT_BELOW || bounds.len() < INSERTION_SORT_BELOW {
                    sort_cell(bounds, pool);
                } else {
                    sort_large_cell(bounds, pool, places);
                }
            }
        }
        grid.cells = Some(CellSize { width: cell_width, height: cell_height });
        true
    }

    /// Back to [`Grid::inactive`], in place.
    pub fn clear(&mut self) {
        self.cells = None;
        self.starts.slots_mut().fill(C::Index::default());
        self.pool.slots_mut().fill(Entry::default());
        self.depth.slots_mut().fill(-N::MAX);
    }

    /// Whether the grid is in use (on, and its pool did not overflow).
    pub fn is_active(&self) -> bool {
        self.cells.is_some()
    }

    /// Cells across and down when the grid is in use.
    pub fn side(&self) -> Option<u16> {
        self.is_active().then_some(self.side)
    }

    /// The entries of the cell holding image pixel (column, row), and the pixel's offsets
    /// from the cell's corner (saturated at 255); `None` when the grid is not active.
    #[inline]
    pub fn cell(&self, column: u16, row: u16) -> Option<CellAt<'_, C>> {
        let CellSize { width, height } = self.cells?;
        Some(GridParts { width, height, side: self.side, starts: self.starts.slots(), pool: self.pool.slots(), depth: self.depth.slots() }.cell(column, row))
    }

    /// The built grid as its parts (`None` when it is not active): what [`crate::bake`] writes
    /// into flash, and what [`Grid::cell`] reads.
    #[inline]
    pub fn parts(&self) -> Option<GridParts<'_, N, C::Index>> {
        let CellSize { width, height } = self.cells?;
        let cells = usize::from(self.side) * usize::from(self.side);
        let starts = self.starts.slots().get(..=cells)?;
        let entries = starts.last()?.get();
        Some(GridParts { width, height, side: self.side, starts, pool: self.pool.slots().get(..entries)?, depth: self.depth.slots().get(..entries)? })
    }

    /// Holds a grid baked for the view the scene is prepared for (`None`: no grid), read
    /// through the `Config`'s storage from now on: inactive when the storage cannot hold it.
    pub fn hold(&mut self, parts: Option<GridParts<'static, N, C::Index>>) {
        self.cells = None;
        let Some(parts) = parts else { return };
        let whole = self.starts.hold(parts.starts) == parts.starts.len() && self.pool.hold(parts.pool) == parts.pool.len() && self.depth.hold(parts.depth) == parts.depth.len();
        if whole {
            self.side = parts.side;
            self.cells = Some(CellSize { width: parts.width, height: parts.height });
        }
    }

    /// Total entries over all cells.
    pub fn entries(&self) -> usize {
        self.starts.slots().get(usize::from(self.side) * usize::from(self.side)).map_or(0, |entries| entries.get())
    }
}

/// A built grid by its parts, borrowed: a [`Grid`]'s own, or a baked scene's, made at build
/// time for its fixed view and kept in flash.
#[derive(Clone, Copy, Debug)]
pub struct GridParts<'a, N, I> {
    /// A cell's pixels across and down.
    pub width: NonZeroU16,
    pub height: NonZeroU16,
    /// Cells across and down.
    pub side: u16,
    /// Each cell's first entry, and the end of the last.
    pub starts: &'a [I],
    /// The entries, cell by cell, and each one's depth bound.
    pub pool: &'a [Entry<I>],
    pub depth: &'a [N],
}

impl<'a, N, I: Index> GridParts<'a, N, I> {
    /// [`Grid::cell`]: the entries of the cell holding image pixel (column, row), and the
    /// pixel's offsets from the cell's corner (saturated at 255).
    #[inline]
    pub fn cell(&self, column: u16, row: u16) -> (&'a [Entry<I>], &'a [N], u16, u16) {
        let (width, height) = (self.width.get(), self.height.get());
        let (cell_column, cell_row) = ((column / width).min(self.side.saturating_sub(1)), (row / height).min(self.side.saturating_sub(1)));
        let cell = usize::from(cell_row) * usize::from(self.side) + usize::from(cell_column);
        let Some(&[start, end]) = self.starts.get(cell..cell + 2) else { return (&[], &[], 0, 0) };
        let (start, end) = (start.get(), end.get());
        let dx = (column - cell_column * width).min(255);
        let dy = (row - cell_row * height).min(255);
        (self.pool.get(start..end).unwrap_or(&[]), self.depth.get(start..end).unwrap_or(&[]), dx, dy)
    }

    /// Its entries.
    pub fn entries(&self) -> usize {
        self.pool.len()
    }
}

/// Sorts one cell's entries by their bounds (stable: insertion sort, with pattern-matched pairs
/// so that no index can be out of range).
#[allow(clippy::neg_cmp_op_on_partial_ord, reason = "`!(b < a)` is meant: it also stops at a NaN bound, where `b >= a` would not")]
fn sort_cell<N: Number, I: Index>(bounds: &mut [N], pool: &mut [Entry<I>]) {
    for i in 1..bounds.len().min(pool.len()) {
        let mut j = i;
        while j > 0 {
            let (Some([a, b]), Some([p, q])) = (bounds.get_mut(j - 1..=j), pool.get_mut(j - 1..=j)) else { break };
            if !(*b < *a) {
                break;
            }
            core::mem::swap(a, b);
            core::mem::swap(p, q);
            j -= 1;
        }
    }
}

/// [`sort_cell`] for a cell of many entries (a scene of thousands of objects): a heapsort, ties
/// broken by each entry's position before the sort (noted in `places`), so that the result is
/// the stable sort's.
#[allow(clippy::neg_cmp_op_on_partial_ord, reason = "`!(b < a)`: equal, or unordered (a NaN), then by position")]
fn sort_large_cell<N: Number, I: Index>(bounds: &mut [N], pool: &mut [Entry<I>], places: &mut [I]) {
    for (position, place) in places.iter_mut().enumerate() {
        *place = I::new(position);
    }
    let len = bounds.len().min(pool.len()).min(places.len());
    let mut cell = (bounds, pool, places);
    let key = |cell: &(&mut [N], &mut [Entry<I>], &mut [I]), at: usize| Some((*cell.0.get(at)?, *cell.2.get(at)?));
    heapsort(
        &mut cell,
        len,
        |cell, i, j| match (key(cell, i), key(cell, j)) {
            (Some(a), Some(b)) => a.0 < b.0 || (!(b.0 < a.0) && a.1 < b.1),
            _ => false,
        },
        |cell, i, j| {
            if i < len && j < len && len <= cell.0.len() && len <= cell.1.len() && len <= cell.2.len() {
                cell.0.swap(i, j);
                cell.1.swap(i, j);
                cell.2.swap(i, j);
            }
        },
    );
}

/// Whether a pixel at offsets (dx, dy) in the cell may be covered by the entry's object.
#[inline]
pub fn entry_covers<I>(entry: &Entry<I>, dx: u16, dy: u16) -> bool {
    let inside = |packed: u16, offset: u16| offset >= (packed & 0xFF) && offset <= (packed >> 8);
    inside(entry.columns, dx) && inside(entry.rows, dy)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::{sort_cell, sort_large_cell, Entry};

    /// The heapsort of a large cell gives the insertion sort's order, ties included.
    #[test]
    fn a_large_cell_sorts_as_a_small_one() {
        let mut state = 7u32;
        for count in [0usize, 1, 64, 65, 700] {
            let bounds: Vec<f32> = (0..count)
                .map(|_| {
                    state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                    (state >> 28) as f32
                })
                .collect();
            let pool: Vec<Entry<u16>> = (0..count as u16).map(|object| Entry { object, columns: 0, rows: 0 }).collect();
            let (mut small, mut small_pool) = (bounds.clone(), pool.clone());
            sort_cell(&mut small, &mut small_pool);
            let (mut large, mut large_pool, mut places) = (bounds, pool, std::vec![0u16; count]);
            sort_large_cell(&mut large, &mut large_pool, &mut places);
            assert_eq!(large, small);
            assert_eq!(large_pool, small_pool, "{count} entries");
        }
    }
}
