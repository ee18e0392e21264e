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
//! An antialiased scene (`render::antialias`) is rendered whole by the last pass.
//!
//! `row_done` is called for every row of a pass's band of blocks once the band is drawn, so each
//! row is reported once per pass (four times in all); a display flushes there.

use super::shadow_ray::ShadowCache;
#[cfg(feature = "antialias")]
use super::antialias::render_antialiased;
use super::mode::Mode;
use super::pixel_value::pixel_value;
use super::shadow_tables::with_shadow_culling;
use super::fill::RowCoverage;
use super::shadow_ray::ShadowCulling;
use super::Statistics;
use crate::number::Number;
use crate::pixel::PixelSink;
use crate::config::Config;
use crate::scene::Prepared;

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

/// Every pass in turn, each pass's counts added to `statistics.passes` (the order
/// `Progressive`): one shadow cache and one set of the light's tables for all of them.
pub(super) fn progressive<N, P, S, M, C: Config<Number = N>>(
    scene: &Prepared<C>,
    sink: &mut S,
    statistics: &mut PassStatistics,
    background: P,
    mode: &M,
) where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
    M: Mode<N, Pixel = P>,
{
    with_shadow_culling(scene, |culling| {
        let mut cache = ShadowCache::default();
        for (pass, counts) in statistics.passes.iter_mut().enumerate() {
            trace_pass::<N, P, S, M, C>(scene, sink, counts, pass, &mut cache, culling, background, mode);
        }
    })
}

/// Pass `pass` alone (the order `Pass`), with its own shadow cache and light's tables.
pub(super) fn single_pass<N, P, S, M, C: Config<Number = N>>(
    scene: &Prepared<C>,
    sink: &mut S,
    statistics: &mut Statistics,
    pass: usize,
    background: P,
    mode: &M,
) where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
    M: Mode<N, Pixel = P>,
{
    with_shadow_culling(scene, |culling| {
        trace_pass::<N, P, S, M, C>(scene, sink, statistics, pass, &mut ShadowCache::default(), culling, background, mode);
    })
}

/// Whether pass `pass` traces pixel (`column`, `row`): both multiples of its size, and (after
/// the first pass) not both multiples of the previous pass's.
pub fn traced_in_pass(pass: usize, column: u16, row: u16) -> bool {
    let Some(&size) = PASS_SIZES.get(pass) else { return false };
    let on_grid = |step: u16| column.is_multiple_of(step) && row.is_multiple_of(step);
    on_grid(size) && (pass == 0 || !on_grid(size * 2))
}

#[allow(clippy::too_many_arguments)]
fn trace_pass<N, P, S, M, C: Config<Number = N>>(
    scene: &Prepared<C>,
    sink: &mut S,
    statistics: &mut Statistics,
    pass: usize,
    cache: &mut ShadowCache<C::Index>,
    culling: &[ShadowCulling<'_, N, C::Index>],
    background: P,
    mode: &M,
) where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
    M: Mode<N, Pixel = P>,
{
    let Some(&size) = PASS_SIZES.get(pass) else { return };
    // An antialiased image has no coarse passes: its last pass renders it whole.
    #[cfg(feature = "antialias")]
    if let Some(antialias) = scene.antialias {
        if size == 1 {
            render_antialiased::<N, P, S, M, C>(scene, antialias, sink, statistics, 0..antialias.image.height(), mode, culling);
        }
        return;
    }
    let camera = &scene.camera;
    let (width, height) = (camera.width(), camera.height());
    // In passes after the first, every other block of a row is the previous pass's on the rows
    // that pass traced.
    let step = usize::from(size);
    let mut coverage = RowCoverage::<C>::for_scene(scene);
    for row in (0..height).step_by(step) {
        if let Some(coverage) = coverage.as_mut() {
            coverage.refill(scene, row);
        }
        let block_height = size.min(height - row);
        for column in (0..width).step_by(step) {
            if !traced_in_pass(pass, column, row) {
                continue;
            }
            statistics.pixels += 1;
            let value = if coverage.as_ref().is_some_and(|coverage| !coverage.covers(column)) {
                background
            } else {
                let pixel = camera.pixel(column, row);
                pixel_value::<N, M, C>(scene, mode, pixel, statistics, cache, culling).unwrap_or(background)
            };
            if size == 1 {
                sink.set_pixel(column, row, value);
            } else {
                let block_width = size.min(width - column);
                for y in row..row + block_height {
                    sink.fill_row(column, y, block_width, value);
                }
            }
        }
        for y in row..row + block_height {
            sink.row_done(y);
        }
    }
}

#[cfg(test)]
mod tests;
