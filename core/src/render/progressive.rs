//! Progressive display for slow chips: the image traced coarse to fine, so that the whole
//! picture shows early on a chip that takes seconds per frame.
//!
//! Four passes, of block size 8, 4, 2 and 1 ([`PASS_SIZES`]). Pass 0 traces the pixel at the
//! top left of every 8x8 block (columns and rows that are multiples of 8) and draws it as the
//! whole block; pass `k` traces the pixels whose column and row are multiples of its size `s`
//! but not both multiples of `2s` (the ones no earlier pass traced) and draws each as an `s`x`s`
//! block. Every pixel is traced exactly once over the four passes, and a pass's blocks cover
//! only pixels not yet traced: the blocks of size `s` tile the image, and the only traced pixel
//! inside one is its own top left corner. So every pixel is last written with its own value, and
//! the final image is the normal render's (the order `Whole`), byte for byte.
//!
//! The pixels go straight to the sink (`fill_row` for a block's rows, `set_pixel` in the last
//! pass): it can be a display's own RAM, with no second framebuffer, and it is never read back.
//! The optimizations apply as in the normal render: Extents, Grid and Sortlist through the same
//! per-pixel shading, and Pixelbuffer as a per-pixel coverage test (the same fill
//! ([`super::fill_volumes_rows`]), recorded one row at a time as spans on the stack instead of
//! marked in the sink): a pixel outside every object's fill is the background with no ray.
//!
//! An antialiased scene (`render::antialias`) is rendered whole by the last pass. The loop is
//! the one of every order (`render/walk.rs`).
//!
//! `row_done` is called for every row of a pass's band of blocks once the band is drawn, so each
//! row is reported once per pass (four times in all); a display flushes there.

use super::Statistics;

/// How many passes a progressive render makes.
pub const PASSES: usize = 4;
/// Each pass's block size, coarse to fine.
pub const PASS_SIZES: [u16; PASSES] = [8, 4, 2, 1];

/// The statistics of each pass of a progressive render (`passes[k]` is pass `k`'s, of block
/// size [`PASS_SIZES`]`[k]`): its pixels, the rays it traced and their tests.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PassStatistics {
    pub passes: [Statistics; PASSES],
}

impl PassStatistics {
    /// The whole render's statistics: the sum over the passes.
    pub fn total(&self) -> Statistics {
        let mut total = Statistics::default();
        for pass in &self.passes {
            total.add(pass);
        }
        total
    }
}

/// Whether pass `pass` traces pixel (`column`, `row`): both multiples of its size, and (after
/// the first pass) not both multiples of the previous pass's.
pub fn traced_in_pass(pass: usize, column: u16, row: u16) -> bool {
    let Some(&size) = PASS_SIZES.get(pass) else { return false };
    let on_grid = |step: u16| column.is_multiple_of(step) && row.is_multiple_of(step);
    on_grid(size) && (pass == 0 || !on_grid(size * 2))
}

#[cfg(test)]
mod tests;
