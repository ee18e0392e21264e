//! Tracing a whole image, top row first (digest §3.4), into a [`PixelSink`].

use core::ops::Range;

#[cfg(feature = "antialias")]
use super::antialias::render_antialiased;
use super::fill::fill_volumes_rows;
use super::mode::Mode;
use super::pixel_value::pixel_value;
use super::shadow_ray::ShadowCache;
use super::shadow_tables::with_shadow_culling;
use super::Statistics;
use crate::number::Number;
use crate::pixel::{PixelSink, PixelSource};
use crate::config::Config;
use crate::scene::Prepared;

/// Pixels read back per `read_row` call (a stack buffer; no row-sized buffer is needed).
const READ_CHUNK: usize = 32;

/// The image rows `rows` into a sink that Pixelbuffer's marks are read back from (the orders
/// `Whole` and `Rows`).
#[allow(clippy::too_many_arguments)]
pub(super) fn render_rows<N, P, S, M, C: Config<Number = N>>(
    scene: &Prepared<C>,
    sink: &mut S,
    statistics: &mut Statistics,
    rows: Range<u16>,
    background: P,
    (fill, flood): (P, P),
    mode: &M,
) where
    N: Number,
    P: Copy + PartialEq,
    S: PixelSink<P> + PixelSource<P>,
    M: Mode<N, Pixel = P>,
{
    #[cfg(feature = "antialias")]
    if let Some(antialias) = scene.antialias {
        return with_shadow_culling(scene, |culling| {
            render_antialiased::<N, P, S, M, C>(scene, antialias, sink, statistics, rows, mode, culling)
        });
    }
    let camera = &scene.camera;
    let pixelbuffer = scene.optimizations.pixelbuffer;
    let rows = rows.start..rows.end.min(camera.height());
    if pixelbuffer {
        fill_volumes_rows(scene, sink, fill, flood, rows.clone());
    }
    let mut cache = ShadowCache::default();
    with_shadow_culling(scene, |culling| {
    let mut chunk = [fill; READ_CHUNK];
    let mut chunk_length = 0;
    let width = camera.width();
    for row in rows {
        statistics.pixels += u64::from(width);
        let mut column = 0;
        while column < width {
            if pixelbuffer {
                // Read the row back a chunk at a time, each chunk before any of it is written.
                let offset = usize::from(column) % READ_CHUNK;
                if offset == 0 {
                    chunk = [fill; READ_CHUNK];
                    chunk_length = usize::from(width - column).min(READ_CHUNK);
                    if let Some(part) = chunk.get_mut(..chunk_length) {
                        sink.read_row(column, row, part);
                    }
                }
                // Only a pixel that still holds the flood colour was never filled: the run of
                // them in this chunk gets the background at once.
                let run = chunk.get(offset..chunk_length).map_or(0, |rest| rest.iter().take_while(|value| **value == flood).count());
                if run > 0 {
                    sink.fill_row(column, row, run as u16, background);
                    column += run as u16;
                    continue;
                }
            }
            let pixel = camera.pixel(column, row);
            let value = pixel_value::<N, M, C>(scene, mode, pixel, statistics, &mut cache, culling).unwrap_or(background);
            sink.set_pixel(column, row, value);
            column += 1;
        }
        sink.row_done(row);
    }
    })
}

