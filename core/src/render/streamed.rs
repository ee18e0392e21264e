//! The render for a sink that cannot be read back: rows top first, each row's pixels written
//! once, left to right, and `row_done` after each row, so the sink can send the row on (to a
//! display's own RAM, to a host) and forget it. No framebuffer is needed.
//!
//! Pixelbuffer's fill (§4.7.2) is the same as the order `Whole`'s ([`super::fill_volumes_rows`]),
//! recorded one row at a time as spans on the stack (`RowCoverage`, as the progressive render
//! does) instead of marked in the sink and read back (`PixelSource::read_row`): a pixel outside
//! every object's fill is the background with no ray, a pixel inside is traced. The pixels are
//! traced in the same order with the same caches, so the image and every statistic equal
//! the order `Whole`'s, sized or not (the tests check it: both thesis
//! scenes, every combination of the optimizations, several number types, antialiasing and the
//! ray tree).
//!
//! What the sink sees: for each row, runs of the background (`fill_row`, one per run of pixels
//! outside the fill) and traced pixels (`set_pixel`), covering the row exactly once, then
//! `row_done`. Never `mark_row`. An antialiased scene goes through the same antialiased render as
//! the order `Whole` (it needs no read-back either: one row of corners on the stack).
//!
//! Memory: the row's coverage, 4 bytes an object plus a few, on the stack while the row is
//! traced.
//!
//! Cost: the fill is worked out per row, each object's extent looked up once a row instead of
//! once a frame (measured on the mps2-an386 in `f32`, firmware/README.md, "Memory budget": the
//! lattice's frame 1.0 % more instructions than the framebuffer render's, snooker's 1.7 %
//! fewer, since no flood is marked and read back). With the thesis's tuning (`Tuning::THESIS`,
//! the `f64` silhouettes) each object's volume is projected once a row instead of once a frame.

#[cfg(feature = "antialias")]
use super::antialias::render_antialiased;
use super::fill::RowCoverage;
use super::shadow_ray::ShadowCache;
use super::mode::Mode;
use super::pixel_value::pixel_value;
use super::shadow_tables::with_shadow_culling;
use super::Statistics;
use crate::number::Number;
use crate::pixel::PixelSink;
use crate::config::Config;
use crate::scene::Prepared;

/// The whole image into a sink that is never read (the order `Streamed`).
pub(super) fn streamed<N, P, S, M, C: Config<Number = N>>(
    scene: &Prepared<C>,
    sink: &mut S,
    statistics: &mut Statistics,
    background: P,
    mode: &M,
) where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
    M: Mode<N, Pixel = P>,
{
    let camera = &scene.camera;
    let (width, height) = (camera.width(), camera.height());
    #[cfg(feature = "antialias")]
    if let Some(antialias) = scene.antialias {
        return with_shadow_culling(scene, |culling| {
            render_antialiased::<N, P, S, M, C>(scene, antialias, sink, statistics, 0..height, mode, culling)
        });
    }
    let mut cache = ShadowCache::default();
    with_shadow_culling(scene, |culling| {
        // Made here, not before the shadow tables: the tables' building is then off the stack.
        let mut coverage = RowCoverage::<C>::for_scene(scene);
        let mut trace = |column: u16, row: u16, statistics: &mut Statistics, sink: &mut S| {
            let pixel = camera.pixel(column, row);
            let value = pixel_value::<N, M, C>(scene, mode, pixel, statistics, &mut cache, culling).unwrap_or(background);
            sink.set_pixel(column, row, value);
        };
        for row in 0..height {
            statistics.pixels += u64::from(width);
            if let Some(coverage) = coverage.as_mut() {
                coverage.refill(scene, row);
                runs(coverage.sorted_spans(), width, |covered, from, to| {
                    if covered {
                        for column in from..to {
                            trace(column, row, statistics, sink);
                        }
                    } else {
                        sink.fill_row(from, row, to - from, background);
                    }
                });
            } else {
                for column in 0..width {
                    trace(column, row, statistics, sink);
                }
            }
            sink.row_done(row);
        }
    })
}

/// Splits the columns `0..width` into the runs the fill covers and the runs it does not, in
/// order, calling `run(covered, first, end)` for each (`end` exclusive; runs never empty,
/// neighbours never alike): the spans (sorted by their first column) merged where they overlap
/// or touch, and the gaps between them. `None`: the whole row is covered.
fn runs(spans: Option<&[(u16, u16)]>, width: u16, mut run: impl FnMut(bool, u16, u16)) {
    let Some(spans) = spans else {
        if width > 0 {
            run(true, 0, width);
        }
        return;
    };
    // The columns before `column` are done; `pending` is the covered run being merged.
    let mut column = 0;
    let mut pending: Option<(u16, u16)> = None;
    let mut finish = |(first, end): (u16, u16), column: &mut u16| {
        if first > *column {
            run(false, *column, first);
        }
        run(true, first, end);
        *column = end;
    };
    for &(first, span_width) in spans {
        let (start, end) = (first.min(width), first.saturating_add(span_width).min(width));
        if start >= end {
            continue;
        }
        pending = match pending {
            Some((from, to)) if start <= to => Some((from, to.max(end))),
            Some(done) => {
                finish(done, &mut column);
                Some((start, end))
            }
            None => Some((start, end)),
        };
    }
    if let Some(done) = pending {
        finish(done, &mut column);
    }
    if column < width {
        run(false, column, width);
    }
}

#[cfg(test)]
mod tests;
