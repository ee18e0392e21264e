//! The one pixel loop (RTRACE.C `raycast`'s loop over the screen, §3.4 of the digest): every
//! order walks the image through [`walk_image`], with three choices made by type, so nothing
//! is dispatched per pixel:
//!
//! - the [`Walk`]: which rows, in how many passes, each pixel drawn as a block of which size
//!   ([`Band`] for `Whole`, `Rows` and `Streamed`; [`AllPasses`] and [`OnePass`] for the
//!   progressive orders);
//! - the [`Coverage`]: how Pixelbuffer's fill is known (read back from the sink, or spans a row);
//! - the [`Pixels`]: how a covered pixel is computed ([`Plain`]: its primary ray, shadow rays
//!   and ray tree; `Antialiased`: the shared corners of §2.3.3, which apply the fill to their
//!   corner rows themselves).
//!
//! What a sink sees, in every order: for each row, the pixels left to right, each written once
//! (`set_pixel`, or a block's `fill_row`s), a run of background pixels outside the fill as one
//! `fill_row` where the order allows it (not in the progressive passes, whose gaps hold the
//! earlier passes' pixels), then `row_done` for each image row the row's blocks cover. Only the
//! orders `Whole` and `Rows` mark the sink and read it back.

use core::ops::Range;

use super::coverage::Coverage;
use super::mode::Mode;
use super::pixel_value::pixel_value;
use super::progressive::{PassStatistics, PASSES, PASS_SIZES};
use super::shadow_ray::{ShadowCache, ShadowCulling};
use super::Statistics;
use crate::config::Config;
use crate::pixel::PixelSink;
use crate::scene::Prepared;

/// How the image is walked: its passes, their rows and their counts.
pub(crate) trait Walk {
    /// What the render counts.
    type Counts;
    /// Progressive: pass `k` draws the pixels it traces as blocks of `PASS_SIZES[k]`, on the
    /// columns no earlier pass traced; a background pixel is its own block.
    const PROGRESSIVE: bool;
    /// The passes to make (indices into `PASS_SIZES` when progressive).
    fn passes(&self) -> Range<usize>;
    /// The image rows walked (clipped to the image by the loop).
    fn rows(&self, height: u16) -> Range<u16>;
    /// Where pass `pass` counts.
    fn counts<'c>(&self, counts: &'c mut Self::Counts, pass: usize) -> &'c mut Statistics;
}

/// A band of rows, every pixel traced once (orders `Whole`, `Rows`, `Streamed`).
pub(crate) struct Band(pub Range<u16>);

impl Walk for Band {
    type Counts = Statistics;
    const PROGRESSIVE: bool = false;
    fn passes(&self) -> Range<usize> {
        0..1
    }
    fn rows(&self, _height: u16) -> Range<u16> {
        self.0.clone()
    }
    fn counts<'c>(&self, counts: &'c mut Statistics, _pass: usize) -> &'c mut Statistics {
        counts
    }
}

/// Every pass of the progressive render, each counted apart (order `Progressive`).
pub(crate) struct AllPasses;

impl Walk for AllPasses {
    type Counts = PassStatistics;
    const PROGRESSIVE: bool = true;
    fn passes(&self) -> Range<usize> {
        0..PASSES
    }
    fn rows(&self, height: u16) -> Range<u16> {
        0..height
    }
    fn counts<'c>(&self, counts: &'c mut PassStatistics, pass: usize) -> &'c mut Statistics {
        let last = counts.passes.len() - 1;
        &mut counts.passes[pass.min(last)]
    }
}

/// One pass of the progressive render (order `Pass`); a pass beyond the last draws nothing.
pub(crate) struct OnePass(pub usize);

impl Walk for OnePass {
    type Counts = Statistics;
    const PROGRESSIVE: bool = true;
    fn passes(&self) -> Range<usize> {
        self.0..self.0.saturating_add(1)
    }
    fn rows(&self, height: u16) -> Range<u16> {
        0..height
    }
    fn counts<'c>(&self, counts: &'c mut Statistics, _pass: usize) -> &'c mut Statistics {
        counts
    }
}

/// How a pixel the fill covers is computed.
pub(crate) trait Pixels<C: Config> {
    /// The sink's pixel.
    type Pixel: Copy;
    /// Antialiased: the pixels apply the fill themselves (to their corner rows), so every pixel
    /// of a row is asked for, and only in a pass of single pixels.
    const ANTIALIASED: bool;
    /// The image's width and height.
    fn size(&self) -> (u16, u16);
    /// Before the first pixel of `row`.
    #[inline(always)]
    fn begin_row(&mut self, _row: u16, _statistics: &mut Statistics) {}
    /// The pixel at (`column`, `row`).
    fn pixel(&mut self, column: u16, row: u16, statistics: &mut Statistics) -> Self::Pixel;
    /// After the last pixel of `row`.
    #[inline(always)]
    fn end_row(&mut self, _row: u16) {}
}

/// A pixel as its primary ray sees it (its shadow rays, its ray tree), or the background.
pub(crate) struct Plain<'a, 'c, C: Config, M: Mode<C::Number>> {
    pub scene: &'a Prepared<C>,
    pub mode: &'a M,
    pub culling: &'a [ShadowCulling<'c, C::Number, C::Index>],
    pub background: M::Pixel,
    pub cache: ShadowCache<C::Index>,
}

impl<C: Config, M: Mode<C::Number>> Pixels<C> for Plain<'_, '_, C, M>
where
    M::Pixel: Copy,
{
    type Pixel = M::Pixel;
    const ANTIALIASED: bool = false;

    #[inline(always)]
    fn size(&self) -> (u16, u16) {
        (self.scene.camera.width(), self.scene.camera.height())
    }

    #[inline(always)]
    fn pixel(&mut self, column: u16, row: u16, statistics: &mut Statistics) -> M::Pixel {
        let pixel = self.scene.camera.pixel(column, row);
        pixel_value::<C::Number, M, C>(self.scene, self.mode, pixel, statistics, &mut self.cache, self.culling).unwrap_or(self.background)
    }
}

/// The first column pass `pass` (of block `size`) traces on `row`, and the step to the next:
/// after the first pass, on the rows the previous pass traced, every other block is that pass's.
#[inline(always)]
fn progressive_columns(pass: usize, size: u16, row: u16) -> (u16, u16) {
    if pass > 0 && row.is_multiple_of(size * 2) {
        (size, size * 2)
    } else {
        (0, size)
    }
}

/// The loop: for each pass, each row, each run of the row the fill covers or not.
#[inline(always)]
pub(crate) fn walk_image<C, S, W, V, K>(
    scene: &Prepared<C>,
    walk: &W,
    counts: &mut W::Counts,
    sink: &mut S,
    coverage: &mut V,
    pixels: &mut K,
    background: K::Pixel,
) where
    C: Config,
    S: PixelSink<K::Pixel>,
    W: Walk,
    V: Coverage<C, K::Pixel, S>,
    K: Pixels<C>,
{
    let (width, height) = pixels.size();
    for pass in walk.passes() {
        let size = if W::PROGRESSIVE {
            match PASS_SIZES.get(pass) {
                Some(&size) => size,
                None => continue,
            }
        } else {
            1
        };
        // An antialiased image has no coarse passes: the pass of single pixels renders it whole.
        if K::ANTIALIASED && size != 1 {
            continue;
        }
        let statistics = walk.counts(counts, pass);
        let rows = walk.rows(height);
        for row in (rows.start..rows.end.min(height)).step_by(usize::from(size)) {
            let (first, step) = if W::PROGRESSIVE && !K::ANTIALIASED { progressive_columns(pass, size, row) } else { (0, 1) };
            // The columns first, first + step, ... below the width (checked: no panic path).
            if let Some(after_first) = (width.saturating_sub(first).saturating_sub(1)).checked_div(step).filter(|_| first < width) {
                statistics.pixels += u64::from(after_first) + 1;
            }
            coverage.begin_row(scene, row);
            pixels.begin_row(row, statistics);
            let block_height = size.min(height - row);
            let mut column = first;
            while column < width {
                let (covered, end) = coverage.run(sink, row, column, width);
                if !covered && !W::PROGRESSIVE {
                    sink.fill_row(column, row, end - column, background);
                    column = end;
                    continue;
                }
                while column < end {
                    let value = if covered { pixels.pixel(column, row, statistics) } else { background };
                    if size == 1 {
                        sink.set_pixel(column, row, value);
                    } else {
                        let block_width = size.min(width - column);
                        for y in row..row + block_height {
                            sink.fill_row(column, y, block_width, value);
                        }
                    }
                    column = column.saturating_add(step);
                }
            }
            pixels.end_row(row);
            for y in row..row + block_height {
                sink.row_done(y);
            }
        }
    }
}

#[cfg(test)]
mod tests;
