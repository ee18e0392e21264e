//! The one door to a render: [`render`]`(&scene, mode, order, sink, counts)`.
//!
//! The mode is what a pixel is ([`Pga`]: a palette index, §4.2.4; [`Rgb`]: 8-bit channels); the
//! order is how the image is walked and what the sink must do:
//!
//! | order | pixels | the sink | counts |
//! |---|---|---|---|
//! | [`Whole`] | every row, top first (digest §3.4) | [`PixelSink`] + [`PixelSource`]: Pixelbuffer's marks are read back | [`Statistics`] |
//! | [`Rows`] | the band of rows given, for one of several threads: each pixel as the whole render's; the counts the band's (the caches start empty at its first row) | as `Whole` | [`Statistics`] |
//! | [`Streamed`] | every row, top first, each pixel written once, then `row_done` | a [`PixelSink`] never read back | [`Statistics`] |
//! | [`Progressive`] | four passes, coarse to fine (`render/progressive.rs`) | a [`PixelSink`] | [`PassStatistics`] |
//! | [`Pass`] | one pass of the progressive render | a [`PixelSink`] | [`Statistics`] |
//!
//! Every order gives the same final image, and `Whole`, `Streamed` and `Progressive` the same
//! statistics (summed over the passes). Antialiasing and the ray tree are the scene's: how a
//! pixel is computed, the same in every order. The stack a render takes is the scene's
//! [`Config`]'s: a ray tree at most `TREE_DEPTH` generations deep (a scene's deeper `depth` is
//! cut there) and a row of antialiasing corners (`CornerRow`).

use core::ops::Range;

#[cfg(feature = "antialias")]
use super::antialias::walk_antialiased;
use super::coverage::{Coverage, ReadBack, RowCoverage};
use super::fill::{PGA_FILL, PGA_FLOOD, RGB_FILL, RGB_FLOOD};
use super::mode::{Mode, PgaNodes, RgbNodes};
use super::progressive::PassStatistics;
use super::shadow_ray::ShadowCache;
use super::shadow_tables::with_shadow_culling;
use super::walk::{walk_image, AllPasses, Band, OnePass, Plain, Walk};
use super::Statistics;
use crate::model::Rgb888;
use crate::number::Number;
use crate::pixel::{PixelSink, PixelSource};
use crate::config::Config;
use crate::scene::Prepared;

/// What a pixel is: [`Pga`] or [`Rgb`].
pub trait PixelMode: sealed::Sealed + Copy {
    /// The pixel's type: a palette index, or 8-bit red, green and blue.
    type Pixel: Copy + PartialEq;
}

/// PGA mode: one palette index per pixel (the thesis's 256-colour display).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pga;

/// RGB mode: 8 bits a channel (see `shading::rgb` for how it differs from the thesis).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rgb;

impl PixelMode for Pga {
    type Pixel = u8;
}

impl PixelMode for Rgb {
    type Pixel = Rgb888;
}

/// The whole image into a sink that Pixelbuffer's marks are read back from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Whole;

/// The image rows in the range only, into a sink that is read back (a band for a thread).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Rows(pub Range<u16>);

/// The whole image into a sink that is never read: each row written once, then `row_done`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Streamed;

/// The whole image coarse to fine, in [`super::PASSES`] passes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Progressive;

/// One pass (0..[`super::PASSES`]) of the progressive render, for a caller that does something
/// between passes: 0, 1, 2, 3 in turn make the whole render. A pass beyond the last does
/// nothing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Pass(pub usize);

/// How an image is walked, for pixels of mode `M` into a sink `S`: the orders above.
pub trait Order<M: PixelMode, S>: sealed::Sealed {
    /// What the render counts: [`Statistics`], or one per pass.
    type Counts;

    /// Renders `scene` in this order; [`render`] calls it.
    #[doc(hidden)]
    fn walk<N: Number, C: Config<Number = N>>(self, scene: &Prepared<C>, sink: &mut S, counts: &mut Self::Counts);
}

/// Renders `scene` in `mode`, walking the image in `order`, into `sink`, adding what it counts
/// to `counts` (the statistics of Table 4.2).
#[inline]
pub fn render<N, C, M, W, S>(scene: &Prepared<C>, mode: M, order: W, sink: &mut S, counts: &mut W::Counts)
where
    N: Number,
    C: Config<Number = N>,
    M: PixelMode,
    W: Order<M, S>,
{
    let _ = mode;
    order.walk::<N, C>(scene, sink, counts);
}

/// Renders `scene` in `walk`'s order into `sink`: the light's shadow tables made once, then each
/// pass. `coverage` makes Pixelbuffer's coverage once the tables are made (so that its room is
/// not held while they are built); an antialiased scene takes its own.
#[inline(always)]
fn render_walk<C, M, S, W, V>(
    scene: &Prepared<C>,
    mode: &M,
    walk: W,
    counts: &mut W::Counts,
    sink: &mut S,
    background: M::Pixel,
    coverage: impl FnOnce(&mut S) -> V,
) where
    C: Config,
    M: Mode<C::Number>,
    M::Pixel: Copy,
    S: PixelSink<M::Pixel>,
    W: Walk,
    V: Coverage<C, M::Pixel, S>,
{
    #[cfg(feature = "antialias")]
    if let Some(antialias) = scene.antialias {
        return with_shadow_culling(scene, |culling| {
            walk_antialiased(scene, mode, antialias, culling, &walk, counts, sink, background)
        });
    }
    with_shadow_culling(scene, |culling| {
        let mut coverage = coverage(sink);
        let mut pixels = Plain { scene, mode, culling, background, cache: ShadowCache::default() };
        walk_image(scene, &walk, counts, sink, &mut coverage, &mut pixels, background);
    })
}

/// The orders for one mode: its nodes, its background and Pixelbuffer's two marks. Each is the
/// one loop (`render/walk.rs`) with its walk and its coverage.
macro_rules! orders {
    ($mode:ty, $pixel:ty, $nodes:ident, $background:ident, $marks:expr) => {
        impl<S: PixelSink<$pixel> + PixelSource<$pixel>> Order<$mode, S> for Whole {
            type Counts = Statistics;

            #[inline(always)]
            fn walk<N: Number, C: Config<Number = N>>(self, scene: &Prepared<C>, sink: &mut S, counts: &mut Statistics) {
                Rows(0..scene.viewport().height()).walk::<N, C>(scene, sink, counts);
            }
        }

        impl<S: PixelSink<$pixel> + PixelSource<$pixel>> Order<$mode, S> for Rows {
            type Counts = Statistics;

            #[inline(always)]
            fn walk<N: Number, C: Config<Number = N>>(self, scene: &Prepared<C>, sink: &mut S, counts: &mut Statistics) {
                let rows = self.0.start..self.0.end.min(scene.camera.height());
                render_walk(scene, &$nodes { scene }, Band(rows.clone()), counts, sink, scene.$background(), |sink| ReadBack::marked(scene, sink, rows, $marks));
            }
        }

        impl<S: PixelSink<$pixel>> Order<$mode, S> for Streamed {
            type Counts = Statistics;

            #[inline(always)]
            fn walk<N: Number, C: Config<Number = N>>(self, scene: &Prepared<C>, sink: &mut S, counts: &mut Statistics) {
                render_walk(scene, &$nodes { scene }, Band(0..scene.camera.height()), counts, sink, scene.$background(), |_| RowCoverage::for_scene(scene));
            }
        }

        impl<S: PixelSink<$pixel>> Order<$mode, S> for Progressive {
            type Counts = PassStatistics;

            #[inline(always)]
            fn walk<N: Number, C: Config<Number = N>>(self, scene: &Prepared<C>, sink: &mut S, counts: &mut PassStatistics) {
                render_walk(scene, &$nodes { scene }, AllPasses, counts, sink, scene.$background(), |_| RowCoverage::for_scene(scene));
            }
        }

        impl<S: PixelSink<$pixel>> Order<$mode, S> for Pass {
            type Counts = Statistics;

            #[inline(always)]
            fn walk<N: Number, C: Config<Number = N>>(self, scene: &Prepared<C>, sink: &mut S, counts: &mut Statistics) {
                render_walk(scene, &$nodes { scene }, OnePass(self.0), counts, sink, scene.$background(), |_| RowCoverage::for_scene(scene));
            }
        }
    };
}

orders!(Pga, u8, PgaNodes, background_index, (PGA_FILL, PGA_FLOOD));
orders!(Rgb, Rgb888, RgbNodes, background_rgb, (RGB_FILL, RGB_FLOOD));

mod sealed {
    pub trait Sealed {}
    impl Sealed for super::Pga {}
    impl Sealed for super::Rgb {}
    impl Sealed for super::Whole {}
    impl Sealed for super::Rows {}
    impl Sealed for super::Streamed {}
    impl Sealed for super::Progressive {}
    impl Sealed for super::Pass {}
}
