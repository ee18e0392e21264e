//! Adaptive antialiasing by the shared-corner method (thesis §2.3.3 and fig 2.9, after Whitted
//! 1980): rays through the pixels' corners, (W+1)·(H+1) of them, each shared by the four
//! pixels that meet there; a pixel whose corners differ by more than the threshold (in any
//! 8-bit channel) is split into four, and the five new corners traced, down to the scene's level
//! L; the pixel is the area-weighted mean of its squares' corner means.
//!
//! The camera of an antialiased scene is the sample grid (`PreparedAntialias::sample_grid`):
//! every corner and sub-corner is a "pixel" of it, so the four optimizations serve every ray
//! that leaves the eye as they serve the pixels of a plain render (Pixelbuffer as a per-row
//! coverage test of the corner rows, as in the progressive render; sub-corners are traced
//! without it). Memory: one row of corners (a const generic capacity `ROW`; corners beyond it
//! are traced again by the next row instead of kept) and the subdivision's fixed stack; no
//! frame-sized buffer.
//!
//! Corners are kept as 8-bit RGB (the mode's colour of the sample, clamped and rounded), so
//! the threshold test and the mean are integer arithmetic, the same in every number type. The
//! pixel is the rounded mean; in PGA mode the look-up table's entry nearest it (scene format).

use core::ops::Range;

use heapless::Vec;

use super::fill::RowCoverage;
use super::mode::Mode;
use super::pixel_value::primary_surface_then;
use super::shadow_ray::{ShadowCache, ShadowCulling};
use super::Statistics;
use crate::number::Number;
use crate::pixel::PixelSink;
use crate::config::Config;
use crate::storage::Table;
use crate::scene::{Prepared, PreparedAntialias};

type Rgb = [u8; 3];

/// One square of a pixel's subdivision: its top left sample, its side (in samples), its corners
/// (top left, top right, bottom left, bottom right) and its level.
#[derive(Clone, Copy)]
struct Square {
    x: u16,
    y: u16,
    side: u16,
    corners: [Rgb; 4],
    level: u8,
}

/// Whether the corners' colours differ by more than `threshold` in some channel.
fn differ(corners: &[Rgb; 4], threshold: u8) -> bool {
    (0..3).any(|channel| {
        let values = corners.map(|corner| corner[channel]);
        let (low, high) = values.iter().fold((u8::MAX, 0), |(low, high), value| (low.min(*value), high.max(*value)));
        high - low > threshold
    })
}

/// Traces one sample of the grid and returns its colour.
struct Sampler<'a, 'c, N, M, C: Config> {
    scene: &'a Prepared<C>,
    mode: &'a M,
    culling: &'a [ShadowCulling<'c, N, C::Index>],
}

impl<N: Number, M: Mode<N>, C: Config<Number = N>> Sampler<'_, '_, N, M, C> {
    fn sample(&self, x: u16, y: u16, statistics: &mut Statistics, cache: &mut ShadowCache<C::Index>) -> Rgb {
        let pixel = self.scene.camera.pixel(x, y);
        let surface = primary_surface_then(self.scene, pixel, statistics, cache, self.culling, |at, material, lighting, statistics, cache| {
            let local = self.mode.local(material, lighting, pixel);
            #[cfg(feature = "ray-tree")]
            if self.scene.has_ray_tree() {
                let context = super::ray_tree::TreeContext { scene: self.scene, colours: self.mode, pixel, culling: self.culling };
                if let Some(mixed) = super::ray_tree::trace_tree::<N, M, C>(&context, *at, local, statistics, cache) {
                    return mixed;
                }
            }
            #[cfg(not(feature = "ray-tree"))]
            let _ = (at, statistics, cache);
            local
        });
        to_rgb(surface.unwrap_or_else(|| self.mode.background()), self.scene)
    }
}

fn to_rgb<N: Number, C: Config<Number = N>>(colour: [N; 3], scene: &Prepared<C>) -> Rgb {
    colour.map(|channel| (channel + scene.constants.half).floor_to_i32().clamp(0, 255) as u8)
}

/// Renders the image rows `rows` of an antialiased scene into `sink`, the pixels in the mode's
/// values (`Mode::averaged`).
#[allow(clippy::too_many_arguments)]
pub(crate) fn render_antialiased<N, P, S, M, C: Config<Number = N>>(
    scene: &Prepared<C>,
    antialias: PreparedAntialias,
    sink: &mut S,
    statistics: &mut Statistics,
    rows: Range<u16>,
    mode: &M,
    culling: &[ShadowCulling<'_, N, C::Index>],
) where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
    M: Mode<N, Pixel = P>,
{
    let sampler = Sampler::<N, M, C> { scene, mode, culling };
    let (width, height) = (antialias.image.width(), antialias.image.height());
    let step = antialias.step();
    let rows = rows.start..rows.end.min(height);
    let mut cache = ShadowCache::default();
    // A corner row's sample, with Pixelbuffer's coverage of that row (uncovered: background).
    let corner = |x: u16, y: u16, coverage: &Option<RowCoverage<C>>, statistics: &mut Statistics, cache: &mut ShadowCache<C::Index>| {
        if coverage.as_ref().is_some_and(|coverage| !coverage.covers(x)) {
            to_rgb(mode.background(), scene)
        } else {
            sampler.sample(x, y, statistics, cache)
        }
    };
    // Each made once, and refilled for every corner row.
    let refilled = |coverage: &mut Option<RowCoverage<C>>, y: u16| {
        if let Some(coverage) = coverage.as_mut() {
            coverage.refill(scene, y);
        }
    };
    let mut corners = C::CornerRow::filled(usize::from(width) + 1, [0; 3]);
    let top = corners.slots_mut();
    let Some(first) = rows.clone().next() else { return };
    let mut coverage = RowCoverage::<C>::for_scene(scene);
    // The row above's coverage, for corners beyond the row's capacity (traced again).
    let mut top_coverage = if usize::from(width) < top.len() { None } else { RowCoverage::<C>::for_scene(scene) };
    refilled(&mut coverage, first * step);
    for (column, slot) in (0..=width).zip(top.iter_mut()) {
        *slot = corner(column * step, first * step, &coverage, statistics, &mut cache);
    }
    for row in rows {
        statistics.pixels += u64::from(width);
        let (y, below) = (row * step, (row + 1) * step);
        refilled(&mut top_coverage, y);
        refilled(&mut coverage, below);
        let mut bottom_left = corner(0, below, &coverage, statistics, &mut cache);
        for column in 0..width {
            let x = column * step;
            // The top corners from the row above, or traced again beyond the row's capacity.
            let above = |index: u16, statistics: &mut Statistics, cache: &mut ShadowCache<C::Index>| match top.get(usize::from(index)) {
                Some(kept) => *kept,
                None => corner(index * step, y, &top_coverage, statistics, cache),
            };
            let top_left = above(column, statistics, &mut cache);
            let top_right = above(column + 1, statistics, &mut cache);
            let bottom_right = corner(x + step, below, &coverage, statistics, &mut cache);
            let mean = pixel_mean(&sampler, Square { x, y, side: step, corners: [top_left, top_right, bottom_left, bottom_right], level: 0 }, antialias, statistics, &mut cache);
            sink.set_pixel(column, row, mode.averaged(mean, antialias.image.x1 + column, antialias.image.y2 - row));
            if let Some(slot) = top.get_mut(usize::from(column)) {
                *slot = bottom_left;
            }
            bottom_left = bottom_right;
        }
        if let Some(slot) = top.get_mut(usize::from(width)) {
            *slot = bottom_left;
        }
        sink.row_done(row);
    }
}

/// The area-weighted mean of one pixel, subdividing where its corners differ.
fn pixel_mean<N: Number, M: Mode<N>, C: Config<Number = N>>(
    sampler: &Sampler<'_, '_, N, M, C>,
    pixel: Square,
    antialias: PreparedAntialias,
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
) -> Rgb {
    // Each split replaces one square by four: at most 3 per level waiting, plus one.
    let mut stack: Vec<Square, 16> = Vec::new();
    let mut sum = [0u32; 3];
    if stack.push(pixel).is_err() {
        return pixel.corners[0];
    }
    while let Some(square) = stack.pop() {
        if square.level < antialias.levels && square.side >= 2 && differ(&square.corners, antialias.threshold) {
            let half = square.side / 2;
            let (x, y, side) = (square.x, square.y, square.side);
            let [top_left, top_right, bottom_left, bottom_right] = square.corners;
            let top = sampler.sample(x + half, y, statistics, cache);
            let left = sampler.sample(x, y + half, statistics, cache);
            let centre = sampler.sample(x + half, y + half, statistics, cache);
            let right = sampler.sample(x + side, y + half, statistics, cache);
            let bottom = sampler.sample(x + half, y + side, statistics, cache);
            let level = square.level + 1;
            for child in [
                Square { x, y, side: half, corners: [top_left, top, left, centre], level },
                Square { x: x + half, y, side: half, corners: [top, top_right, centre, right], level },
                Square { x, y: y + half, side: half, corners: [left, centre, bottom_left, bottom], level },
                Square { x: x + half, y: y + half, side: half, corners: [centre, right, bottom, bottom_right], level },
            ] {
                // 3·L + 1 ≤ 13 squares wait at once.
                let _ = stack.push(child);
            }
        } else {
            let area = u32::from(square.side) * u32::from(square.side);
            for (channel, total) in sum.iter_mut().enumerate() {
                *total += area * square.corners.iter().map(|corner| u32::from(corner[channel])).sum::<u32>();
            }
        }
    }
    let whole = 4 * u32::from(pixel.side) * u32::from(pixel.side);
    // `whole` is never zero (a pixel's side is at least one sample); checked, so no panic path.
    sum.map(|total| (total + whole / 2).checked_div(whole).unwrap_or(0).min(255) as u8)
}
