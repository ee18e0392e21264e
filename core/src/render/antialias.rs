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

use heapless::Vec;

use super::coverage::RowCoverage;
use super::mode::Mode;
use super::pixel_value::primary_surface_then;
use super::shadow_ray::{ShadowCache, ShadowCulling};
use super::walk::{walk_image, Pixels, Walk};
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
    // Any value below zero clamps to 0 whether it was floored or truncated.
    colour.map(|channel| (channel + scene.constants.half).to_i32_monotone().clamp(0, 255) as u8)
}

/// The pixels of an antialiased image: each the mean of its corners, subdivided where they
/// differ. A row of corners is kept from one image row to the next (the top corners of the
/// next), and Pixelbuffer's fill applies to the corner rows (a corner outside it is the
/// background with no ray).
struct Antialiased<'a, 'c, C: Config, M> {
    sampler: Sampler<'a, 'c, C::Number, M, C>,
    antialias: PreparedAntialias,
    /// The corners above the row: the row of corners below the previous row.
    top: C::CornerRow,
    /// The fill of the row of corners below the row.
    coverage: Option<RowCoverage<C>>,
    /// The fill of the row of corners above, for the corners beyond the row's room (traced
    /// again).
    top_coverage: Option<RowCoverage<C>>,
    bottom_left: Rgb,
    cache: ShadowCache<C::Index>,
    started: bool,
}

impl<C: Config, M: Mode<C::Number>> Antialiased<'_, '_, C, M> {
    /// A corner row's sample, with the fill of that row (uncovered: the background).
    #[inline(always)]
    fn corner(&mut self, x: u16, y: u16, below: bool, statistics: &mut Statistics) -> Rgb {
        let coverage = if below { &mut self.coverage } else { &mut self.top_coverage };
        if coverage.as_mut().is_some_and(|coverage| !coverage.covers(x)) {
            to_rgb(self.sampler.mode.background(), self.sampler.scene)
        } else {
            self.sampler.sample(x, y, statistics, &mut self.cache)
        }
    }

    fn refill(coverage: &mut Option<RowCoverage<C>>, scene: &Prepared<C>, y: u16) {
        if let Some(coverage) = coverage.as_mut() {
            coverage.refill(scene, y);
        }
    }
}

impl<C: Config, M: Mode<C::Number>> Pixels<C> for Antialiased<'_, '_, C, M>
where
    M::Pixel: Copy,
{
    type Pixel = M::Pixel;
    const ANTIALIASED: bool = true;

    fn size(&self) -> (u16, u16) {
        (self.antialias.image.width(), self.antialias.image.height())
    }

    fn begin_row(&mut self, row: u16, statistics: &mut Statistics) {
        let (scene, step, width) = (self.sampler.scene, self.antialias.step(), self.antialias.image.width());
        if !self.started {
            // The first row's top corners.
            self.started = true;
            Self::refill(&mut self.coverage, scene, row * step);
            for column in 0..=width {
                let Some(_) = self.top.slots().get(usize::from(column)) else { break };
                let corner = self.corner(column * step, row * step, true, statistics);
                if let Some(slot) = self.top.slots_mut().get_mut(usize::from(column)) {
                    *slot = corner;
                }
            }
        }
        let (y, below) = (row * step, (row + 1) * step);
        Self::refill(&mut self.top_coverage, scene, y);
        Self::refill(&mut self.coverage, scene, below);
        self.bottom_left = self.corner(0, below, true, statistics);
    }

    fn pixel(&mut self, column: u16, row: u16, statistics: &mut Statistics) -> M::Pixel {
        let step = self.antialias.step();
        let (x, y, below) = (column * step, row * step, (row + 1) * step);
        // The top corners from the row above, or traced again beyond the row's room.
        let above = |this: &mut Self, index: u16, statistics: &mut Statistics| match this.top.slots().get(usize::from(index)) {
            Some(kept) => *kept,
            None => this.corner(index * step, y, false, statistics),
        };
        let top_left = above(self, column, statistics);
        let top_right = above(self, column + 1, statistics);
        let bottom_right = self.corner(x + step, below, true, statistics);
        let square = Square { x, y, side: step, corners: [top_left, top_right, self.bottom_left, bottom_right], level: 0 };
        let mean = pixel_mean(&self.sampler, square, self.antialias, statistics, &mut self.cache);
        if let Some(slot) = self.top.slots_mut().get_mut(usize::from(column)) {
            *slot = self.bottom_left;
        }
        self.bottom_left = bottom_right;
        let image = self.antialias.image;
        self.sampler.mode.averaged(mean, image.x1 + column, image.y2 - row)
    }

    fn end_row(&mut self, _row: u16) {
        let width = self.antialias.image.width();
        if let Some(slot) = self.top.slots_mut().get_mut(usize::from(width)) {
            *slot = self.bottom_left;
        }
    }
}

/// An antialiased scene in `walk`'s order: the image loop with [`Antialiased`] pixels and no
/// coverage of its own (the pixels apply the fill to their corner rows). Out of line, so that
/// the row of corners is not in a plain render's frame.
#[allow(clippy::too_many_arguments)]
#[inline(never)]
pub(super) fn walk_antialiased<C, M, S, W>(
    scene: &Prepared<C>,
    mode: &M,
    antialias: PreparedAntialias,
    culling: &[ShadowCulling<'_, C::Number, C::Index>],
    walk: &W,
    counts: &mut W::Counts,
    sink: &mut S,
    background: M::Pixel,
) where
    C: Config,
    M: Mode<C::Number>,
    M::Pixel: Copy,
    S: PixelSink<M::Pixel>,
    W: Walk,
{
    let width = usize::from(antialias.image.width());
    // The row of corners made in place (a move would copy it on the stack).
    let mut pixels = Antialiased::<C, M> {
        sampler: Sampler { scene, mode, culling },
        antialias,
        top: C::CornerRow::filled(width + 1, [0; 3]),
        coverage: RowCoverage::<C>::for_scene(scene),
        top_coverage: None,
        bottom_left: [0; 3],
        cache: ShadowCache::default(),
        started: false,
    };
    // The row above's coverage, for corners beyond the row's room (traced again).
    if width >= pixels.top.slots().len() {
        pixels.top_coverage = RowCoverage::<C>::for_scene(scene);
    }
    walk_image(scene, walk, counts, sink, &mut None::<RowCoverage<C>>, &mut pixels, background);
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
