//! Grid (§4.7.4, `makegrid`): the screen cut into 20x20 cells, each with the objects whose
//! extent overlaps it, in test order (so with Sortlist each cell list stays sorted).
//!
//! No heap: the cell lists share one pool of `POOL_PER_OBJECT · MAX_OBJECTS` object numbers
//! (`u16`), with 401 `u16` start offsets. The cell size is the thesis's
//! `(pixels − 1)/20 + 1`. A cell list simply ends at the next cell's start (the thesis's
//! NULL-dereferencing `nextobject`, digest B4, cannot happen). Should a scene need more entries
//! than the pool holds, the grid is switched off for that scene (every object is a candidate),
//! which changes speed, never the image.

use super::extents::Extent;

/// Cells across and down (`GRIDCOL`, `GRIDROW`).
pub const GRID_SIZE: u16 = 20;
const CELLS: usize = GRID_SIZE as usize * GRID_SIZE as usize;
/// Pool entries per object: an object's extent may overlap this many cells on average.
pub const POOL_PER_OBJECT: usize = 32;

#[derive(Clone, Debug)]
pub struct Grid<const MAX_OBJECTS: usize> {
    /// False when the grid is off or its pool overflowed.
    pub active: bool,
    cell_width: u16,
    cell_height: u16,
    starts: [u16; CELLS + 1],
    pool: [[u16; POOL_PER_OBJECT]; MAX_OBJECTS],
}

impl<const MAX_OBJECTS: usize> Grid<MAX_OBJECTS> {
    pub fn inactive() -> Self {
        Self { active: false, cell_width: 1, cell_height: 1, starts: [0; CELLS + 1], pool: [[0; POOL_PER_OBJECT]; MAX_OBJECTS] }
    }

    /// `order`: the objects in test order; `extents` indexed by object number.
    pub fn build(width: u16, height: u16, order: &[u16], extents: &[Extent]) -> Self {
        let mut grid = Self::inactive();
        grid.cell_width = (width - 1) / GRID_SIZE + 1;
        grid.cell_height = (height - 1) / GRID_SIZE + 1;
        let capacity = (POOL_PER_OBJECT * MAX_OBJECTS).min(u16::MAX as usize);
        let pool = grid.pool.as_flattened_mut();
        let mut used = 0usize;
        for cell in 0..CELLS {
            grid.starts[cell] = used as u16;
            let (row, column) = ((cell / GRID_SIZE as usize) as u32, (cell % GRID_SIZE as usize) as u32);
            let (x1, y1) = (column * u32::from(grid.cell_width), row * u32::from(grid.cell_height));
            let (x2, y2) = (x1 + u32::from(grid.cell_width) - 1, y1 + u32::from(grid.cell_height) - 1);
            for &object in order {
                let Some(extent) = extents.get(usize::from(object)) else { continue };
                if extent.is_empty() {
                    continue;
                }
                let overlaps = u32::from(extent.first_column) <= x2
                    && u32::from(extent.last_column) >= x1
                    && u32::from(extent.first_row) <= y2
                    && u32::from(extent.last_row) >= y1;
                if overlaps {
                    if used >= capacity {
                        return Self::inactive();
                    }
                    pool[used] = object;
                    used += 1;
                }
            }
        }
        grid.starts[CELLS] = used as u16;
        grid.active = true;
        grid
    }

    /// The candidate list of the cell holding image pixel (column, row).
    #[inline]
    pub fn cell(&self, column: u16, row: u16) -> &[u16] {
        let (cell_column, cell_row) = (column / self.cell_width, row / self.cell_height);
        let cell = usize::from(cell_row.min(GRID_SIZE - 1)) * GRID_SIZE as usize + usize::from(cell_column.min(GRID_SIZE - 1));
        let (start, end) = (usize::from(self.starts[cell]), usize::from(self.starts[cell + 1]));
        self.pool.as_flattened().get(start..end).unwrap_or(&[])
    }

    /// Total entries over all cells.
    pub fn entries(&self) -> usize {
        usize::from(self.starts[CELLS])
    }
}
