//! Tracing a whole image, top row first (digest §3.4), into a [`PixelSink`].

use core::ops::Range;

use super::antialias::{render_antialiased, ANTIALIAS_ROW};
use super::fill::{fill_volumes_rows, PGA_FILL, RGB_FILL};
use super::mode::{Mode, PgaNodes, RgbNodes};
use super::pixel_value::pixel_value;
use super::shadow_ray::ShadowCache;
use super::shadow_tables::with_shadow_culling;
use super::Statistics;
use crate::model::{Rgb888, MAX_DEPTH};
use crate::number::Number;
use crate::pixel::{PixelSink, PixelSource};
use crate::scene::{Objects, Scene};

/// Renders the scene in PGA mode: one palette index per pixel, rows top first, calling
/// `row_done` after each row.
pub fn render_pga<N, S, const MAX_OBJECTS: usize, O: Objects<N>>(scene: &Scene<N, MAX_OBJECTS, O>, sink: &mut S, statistics: &mut Statistics)
where
    N: Number,
    S: PixelSink<u8> + PixelSource<u8>,
{
    render_pga_rows(scene, sink, statistics, 0..scene.viewport().height())
}

/// [`render_pga`] with its stack sized for the scene (the firmware's): an explicit stack for a
/// ray tree at most `DEPTH` generations deep (a scene's deeper `depth` is cut there;
/// [`render_pga`] allows the format's deepest, 8), and a row of `ROW` corners for antialiasing
/// (the image's width plus one shares every corner; fewer traces some twice).
pub fn render_pga_sized<N, S, const MAX_OBJECTS: usize, O: Objects<N>, const DEPTH: usize, const ROW: usize>(scene: &Scene<N, MAX_OBJECTS, O>, sink: &mut S, statistics: &mut Statistics)
where
    N: Number,
    S: PixelSink<u8> + PixelSource<u8>,
{
    let nodes = PgaNodes { scene };
    render::<N, u8, S, _, MAX_OBJECTS, O, DEPTH, ROW>(scene, sink, statistics, 0..scene.camera.height(), scene.background, (PGA_FILL, PGA_FILL ^ 0xFF), &nodes)
}

/// [`render_pga`] of the image rows `rows` only (a band, for one of several threads): the
/// sink receives only those rows. Every pixel's value equals the whole render's; the
/// statistics are the band's (the hit and shadow caches start empty at its first row).
pub fn render_pga_rows<N, S, const MAX_OBJECTS: usize, O: Objects<N>>(scene: &Scene<N, MAX_OBJECTS, O>, sink: &mut S, statistics: &mut Statistics, rows: Range<u16>)
where
    N: Number,
    S: PixelSink<u8> + PixelSource<u8>,
{
    let nodes = PgaNodes { scene };
    render::<N, u8, S, _, MAX_OBJECTS, O, { MAX_DEPTH as usize }, ANTIALIAS_ROW>(scene, sink, statistics, rows, scene.background, (PGA_FILL, PGA_FILL ^ 0xFF), &nodes)
}

/// Renders the scene in RGB mode (see `shading::rgb` for how it differs from the thesis).
pub fn render_rgb<N, S, const MAX_OBJECTS: usize, O: Objects<N>>(scene: &Scene<N, MAX_OBJECTS, O>, sink: &mut S, statistics: &mut Statistics)
where
    N: Number,
    S: PixelSink<Rgb888> + PixelSource<Rgb888>,
{
    render_rgb_rows(scene, sink, statistics, 0..scene.viewport().height())
}

/// [`render_rgb`] of the image rows `rows` only (see [`render_pga_rows`]).
pub fn render_rgb_rows<N, S, const MAX_OBJECTS: usize, O: Objects<N>>(scene: &Scene<N, MAX_OBJECTS, O>, sink: &mut S, statistics: &mut Statistics, rows: Range<u16>)
where
    N: Number,
    S: PixelSink<Rgb888> + PixelSource<Rgb888>,
{
    let nodes = RgbNodes { scene };
    render::<N, Rgb888, S, _, MAX_OBJECTS, O, { MAX_DEPTH as usize }, ANTIALIAS_ROW>(scene, sink, statistics, rows, scene.background_rgb(), (RGB_FILL, RGB_FILL.map(|c| c ^ 0xFF)), &nodes)
}

/// Pixels read back per `read_row` call (a stack buffer; no row-sized buffer is needed).
const READ_CHUNK: usize = 32;

fn render<N, P, S, M, const MAX_OBJECTS: usize, O: Objects<N>, const DEPTH: usize, const ROW: usize>(
    scene: &Scene<N, MAX_OBJECTS, O>,
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
    if let Some(antialias) = scene.antialias {
        return with_shadow_culling(scene, |culling| {
            render_antialiased::<N, P, S, M, MAX_OBJECTS, O, DEPTH, ROW>(scene, antialias, sink, statistics, rows, mode, culling)
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
            let value = pixel_value::<N, M, MAX_OBJECTS, O, DEPTH>(scene, mode, pixel, statistics, &mut cache, culling).unwrap_or(background);
            sink.set_pixel(column, row, value);
            column += 1;
        }
        sink.row_done(row);
    }
    })
}

