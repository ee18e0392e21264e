//! A uniform 3-D grid for secondary rays (thesis §5.2.1: "uniform space subdivision", after
//! Fujimoto et al.): the box around the objects' bounding spheres cut into up to 8x8x8 cells,
//! each listing the objects whose sphere (widened by a margin) reaches it. A reflected or
//! refracted ray walks the cells it passes through in order (Amanatides and Woo's traversal)
//! and tests only their objects, each once, stopping at the first cell that ends beyond the
//! nearest hit found.
//!
//! Fixed capacity: at most [`CELLS`] cells and [`ENTRIES_PER_OBJECT`] cell entries per object on average; an
//! object that would take more than [`LARGE_OBJECT_CELLS`] cells (a floor, a wall) is kept out of
//! the cells and tested by every ray. When the entries do not fit, or in a type whose
//! directions are too coarse for the margins (`Number::SHADOW_CULLING_HOLDS` false), there is
//! no grid and secondary rays test every object's bounding sphere instead.
//!
//! Built from the spheres in the number type at preparation (on the chip too: it depends only
//! on the objects, and costs a division per object and axis).

use crate::geometry::{Ray, Vector3};
use crate::config::{Config, SPACE_ENTRIES_PER_OBJECT};
use crate::storage::{Index, Table, Unset};
use crate::number::Number;
use crate::optimize::bounding_sphere::BoundingSphere;
use crate::optimize::shadow_culling::BlockerSet;

/// Cells per axis at most.
pub const MAX_RESOLUTION: usize = 8;
/// Cells at most.
pub const CELLS: usize = MAX_RESOLUTION * MAX_RESOLUTION * MAX_RESOLUTION;
/// Cell entries per object on average at most (else no grid).
pub const ENTRIES_PER_OBJECT: usize = SPACE_ENTRIES_PER_OBJECT;
/// An object reaching more cells than this is tested by every ray instead.
pub const LARGE_OBJECT_CELLS: usize = 64;

pub struct SpaceGrid<C: Config> {
    /// Cells per axis (0: no grid).
    resolution: usize,
    low: Vector3<C::Number>,
    cell: Vector3<C::Number>,
    /// Where each cell's entries start in `entries` (cell `i`'s run is `starts[i]..starts[i+1]`).
    starts: [C::Index; CELLS + 1],
    entries: C::SpaceEntries,
    /// Objects tested by every ray (too large for the cells).
    large: BlockerSet,
    large_beyond: bool,
}

impl<C: Config> core::fmt::Debug for SpaceGrid<C> {
    fn fmt(&self, formatter: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        formatter.debug_struct("SpaceGrid").field("resolution", &self.resolution).field("large", &self.large).field("large_beyond", &self.large_beyond).finish_non_exhaustive()
    }
}

impl<C: Config> Clone for SpaceGrid<C> {
    fn clone(&self) -> Self {
        Self { resolution: self.resolution, low: self.low, cell: self.cell, starts: self.starts, entries: self.entries.clone(), large: self.large, large_beyond: self.large_beyond }
    }
}

impl<C: Config> SpaceGrid<C> {
    pub const NONE: Self = Self {
        resolution: 0,
        low: Unset::UNSET,
        cell: Unset::UNSET,
        starts: Unset::UNSET,
        entries: Unset::UNSET,
        large: BlockerSet::EMPTY,
        large_beyond: false,
    };
}

impl<N: Number, C: Config<Number = N>> SpaceGrid<C> {
    /// No grid, room for `count` objects' entries: [`SpaceGrid::NONE`] for storage sized at
    /// run time.
    pub fn none(count: usize) -> Self {
        Self {
            resolution: 0,
            low: Vector3::zero(),
            cell: Vector3::zero(),
            starts: [C::Index::default(); CELLS + 1],
            entries: C::SpaceEntries::filled(count.saturating_mul(ENTRIES_PER_OBJECT), C::Index::default()),
            large: BlockerSet::EMPTY,
            large_beyond: false,
        }
    }

    /// Whether there is a grid to walk.
    pub fn is_built(&self) -> bool {
        self.resolution > 0
    }

    /// Builds the grid for the objects' spheres (replacing any earlier one); no grid when they do
    /// not fit the capacity.
    pub fn build(&mut self, spheres: &[BoundingSphere<N>]) {
        self.resolution = 0;
        self.large = BlockerSet::EMPTY;
        self.large_beyond = false;
        let Some(first) = spheres.first() else { return };
        if !N::SHADOW_CULLING_HOLDS || spheres.iter().any(|s| s.radius == N::MAX) || spheres.len() > C::MAX_OBJECTS {
            return;
        }
        let mut low = first.centre;
        let mut high = low;
        for s in spheres {
            let r = Vector3 { x: s.radius, y: s.radius, z: s.radius };
            let (a, b) = (s.centre - r, s.centre + r);
            low = Vector3 { x: low.x.min(a.x), y: low.y.min(a.y), z: low.z.min(a.z) };
            high = Vector3 { x: high.x.max(b.x), y: high.y.max(b.y), z: high.z.max(b.z) };
        }
        // About two objects a cell: the cube root of twice the count, 1..=8 a side.
        let mut resolution = 1;
        while resolution < MAX_RESOLUTION && resolution * resolution * resolution < 2 * spheres.len() {
            resolution += 1;
        }
        let n = N::from_i32(resolution as i32);
        let size = high - low;
        let Some(cell) = (|| Some(Vector3 { x: size.x.checked_div(n)?, y: size.y.checked_div(n)?, z: size.z.checked_div(n)? }))() else { return };
        if cell.x <= N::ZERO || cell.y <= N::ZERO || cell.z <= N::ZERO {
            return;
        }
        self.low = low;
        self.cell = cell;
        self.resolution = resolution;
        // Count, then place (a counting sort by cell), over each object's cell box.
        let mut counts = [C::Index::default(); CELLS + 1];
        let mut total = 0usize;
        for (index, s) in spheres.iter().enumerate() {
            match self.cell_box(s) {
                Some((a, b)) => {
                    for cell in Self::cells_of(a, b, resolution) {
                        if let Some(count) = counts.get_mut(cell) {
                            // Wraps only past `Index::MAX` entries in all, and then there is no grid.
                            *count = C::Index::new(count.get() + 1);
                        }
                        total += 1;
                    }
                }
                None => self.mark_large(index),
            }
        }
        // By the scene's own count, not the build's capacity: every build of a scene decides alike.
        if total > ENTRIES_PER_OBJECT * spheres.len() || total > C::Index::MAX {
            self.resolution = 0;
            return;
        }
        let mut start = 0;
        for (slot, count) in self.starts.iter_mut().zip(counts.iter()) {
            *slot = C::Index::new(start);
            start += count.get();
        }
        let mut next = self.starts;
        for (index, s) in spheres.iter().enumerate() {
            if let Some((a, b)) = self.cell_box(s) {
                for cell in Self::cells_of(a, b, resolution) {
                    let Some(position) = next.get_mut(cell) else { continue };
                    if let Some(entry) = self.entries.slots_mut().get_mut(position.get()) {
                        *entry = C::Index::new(index);
                    }
                    *position = C::Index::new(position.get() + 1);
                }
            }
        }
    }

    fn mark_large(&mut self, index: usize) {
        if index < BlockerSet::CAPACITY {
            self.large.insert(index);
        } else {
            self.large_beyond = true;
        }
    }

    /// The cells (inclusive, per axis) a sphere reaches, widened by a sixteenth of a cell, or
    /// `None` for an object too large for the cells.
    fn cell_box(&self, sphere: &BoundingSphere<N>) -> Option<([usize; 3], [usize; 3])> {
        let margin = |cell: N| cell.times_power_of_two(-4);
        let r = sphere.radius;
        let c = sphere.centre.to_array();
        let low = self.low.to_array();
        let cell = self.cell.to_array();
        let mut a = [0usize; 3];
        let mut b = [0usize; 3];
        for axis in 0..3 {
            // Below zero, floored or truncated, clamps to cell 0 either way.
            let index = |value: N| value.checked_div(cell[axis]).map_or(0, |q| q.to_i32_monotone().min(self.resolution as i32 - 1).max(0) as usize);
            a[axis] = index(c[axis] - r - margin(cell[axis]) - low[axis]);
            b[axis] = index(c[axis] + r + margin(cell[axis]) - low[axis]);
        }
        let cells: usize = (0..3).map(|axis| b[axis].saturating_sub(a[axis]) + 1).product();
        (cells <= LARGE_OBJECT_CELLS || self.resolution <= 2).then_some((a, b))
    }

    fn cells_of(a: [usize; 3], b: [usize; 3], resolution: usize) -> impl Iterator<Item = usize> {
        (a[2]..=b[2]).flat_map(move |z| (a[1]..=b[1]).flat_map(move |y| (a[0]..=b[0]).map(move |x| (z * resolution + y) * resolution + x)))
    }

    /// The objects of one cell.
    fn cell_objects(&self, cell: usize) -> &[C::Index] {
        let (Some(&start), Some(&end)) = (self.starts.get(cell), self.starts.get(cell + 1)) else { return &[] };
        self.entries.slots().get(start.get()..end.get()).unwrap_or(&[])
    }

    /// Walks the cells along `ray` in order, calling `test(object)` once per object met (and
    /// first for every large object); `test` returns the nearest hit's `t` so far, and the walk
    /// stops after the first cell that ends beyond it. Objects beyond the first 128 may be
    /// offered more than once (a repeated test finds the same hit).
    pub fn walk(&self, ray: &Ray<N>, object_count: usize, mut test: impl FnMut(usize) -> Option<N>) {
        let mut tested = BlockerSet::EMPTY;
        let mut offer = |index: usize, tested: &mut BlockerSet| -> Option<N> {
            if index < BlockerSet::CAPACITY {
                if tested.contains(index) {
                    return None;
                }
                tested.insert(index);
            }
            test(index)
        };
        let mut best: Option<N> = None;
        let keep = |best: Option<N>, found: Option<N>| match (best, found) {
            (Some(b), Some(f)) => Some(b.min(f)),
            (b, f) => f.or(b),
        };
        for index in 0..object_count {
            let large = if index < BlockerSet::CAPACITY { self.large.contains(index) } else { self.large_beyond };
            if large {
                best = keep(best, offer(index, &mut tested));
            }
        }
        let resolution = self.resolution as i32;
        let origin = ray.origin.to_array();
        let direction = ray.direction.to_array();
        let low = self.low.to_array();
        let cell = self.cell.to_array();
        // The ray's span inside the grid's box (slabs), from t = 0.
        let mut enter = N::ZERO;
        let mut leave = N::MAX;
        for axis in 0..3 {
            let high = low[axis] + cell[axis] * N::from_i32(resolution);
            match (low[axis] - origin[axis]).checked_div(direction[axis]) {
                Some(t0) => {
                    let t1 = (high - origin[axis]).checked_div(direction[axis]).unwrap_or(N::MAX);
                    let (near, far) = if t0 < t1 { (t0, t1) } else { (t1, t0) };
                    enter = enter.max(near);
                    leave = leave.min(far);
                }
                // Parallel to the slab: inside it or never in the box.
                None => {
                    if origin[axis] < low[axis] || origin[axis] > high {
                        return;
                    }
                }
            }
        }
        if enter > leave {
            return;
        }
        // The starting cell, and per axis the step, the t of the next boundary and the t per cell.
        let mut position = [0i32; 3];
        let mut step = [0i32; 3];
        let mut next = [N::MAX; 3];
        let mut delta = [N::MAX; 3];
        for axis in 0..3 {
            let at = origin[axis] + direction[axis] * enter - low[axis];
            // `min` then `max`, not `clamp`: clamp asserts its bounds' order, a panic path.
            // Below zero, floored or truncated, clamps to cell 0 either way.
            let index = at.checked_div(cell[axis]).map_or(0, |q| q.to_i32_monotone()).min(resolution - 1).max(0);
            position[axis] = index;
            if direction[axis] > N::ZERO {
                step[axis] = 1;
                let boundary = low[axis] + cell[axis] * N::from_i32(index + 1);
                next[axis] = (boundary - origin[axis]).checked_div(direction[axis]).unwrap_or(N::MAX);
                delta[axis] = cell[axis].checked_div(direction[axis]).unwrap_or(N::MAX);
            } else if direction[axis] < N::ZERO {
                step[axis] = -1;
                let boundary = low[axis] + cell[axis] * N::from_i32(index);
                next[axis] = (boundary - origin[axis]).checked_div(direction[axis]).unwrap_or(N::MAX);
                delta[axis] = (-cell[axis]).checked_div(direction[axis]).unwrap_or(N::MAX);
            }
        }
        // At most every cell once: a bound on the walk whatever the rounding.
        for _ in 0..3 * self.resolution {
            let cell_index = ((position[2] * resolution + position[1]) * resolution + position[0]) as usize;
            for &object in self.cell_objects(cell_index) {
                best = keep(best, offer(object.get(), &mut tested));
            }
            let axis = if next[0] <= next[1] && next[0] <= next[2] { 0 } else if next[1] <= next[2] { 1 } else { 2 };
            let exit = next[axis];
            // Past the nearest hit (strictly: an equal t in the next cell may be an earlier
            // object's), or out of the grid.
            if best.is_some_and(|t| t < exit) || exit > leave {
                return;
            }
            position[axis] += step[axis];
            if !(0..resolution).contains(&position[axis]) {
                return;
            }
            next[axis] = next[axis] + delta[axis];
        }
    }
}
