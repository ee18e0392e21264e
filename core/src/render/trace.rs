//! Tracing a whole image, top row first (digest §3.4), into a [`PixelSink`].

use core::ops::Range;

use super::antialias::render_antialiased;
use super::lights::direct_lighting;
#[cfg(feature = "ray-tree")]
use super::ray_tree::{trace_tree, TreeContext};
use super::surface::{NodeColours, SurfacePoint};
use super::shadow::{ShadowCache, ShadowCulling};
#[cfg(feature = "acceleration-tables")]
use crate::optimize::shadow::{blocker_table, BlockerSet, DirectionChord, LightPosition, LightReach};
use super::primary::nearest_hit_cached;
use super::Statistics;
use crate::camera::PixelPosition;
use crate::optimize::bounding_volume::ObjectGeometry;
use crate::optimize::extents::Extent;
use crate::optimize::pixelbuffer::hull_span;
use crate::optimize::projection::Projected;
use crate::number::Number;
use crate::pixel::{PixelSink, PixelSource, Rgb888};
#[cfg(feature = "acceleration-tables")]
use crate::scene::{PreparedLight, MAX_LIGHTS};
use crate::scene::{Objects, PreparedMaterial, Scene, MAX_DEPTH};
use crate::shading::{pga_index, rgb_intensity, rgb_pixel, rgb_quantized, Lighting};

/// What a traced pixel saw: nothing, or an object's material lit by `lighting`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadedPixel<N> {
    Background,
    Surface { material: PreparedMaterial<N>, lighting: Lighting<N> },
}

/// Traces one pixel's primary ray and, for a hit, its shadow ray, and evaluates the lighting.
pub fn shade_pixel<N: Number, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
) -> ShadedPixel<N> {
    shade_pixel_cached(scene, pixel, statistics, &mut ShadowCache::default(), &[])
}

fn shade_pixel_cached<N: Number, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
    cache: &mut ShadowCache,
    culling: &[ShadowCulling<'_, N>],
) -> ShadedPixel<N> {
    primary_surface_then(scene, pixel, statistics, cache, culling, |_, material, lighting, _, _| ShadedPixel::Surface { material: *material, lighting })
        .unwrap_or(ShadedPixel::Background)
}

/// The primary ray's hit, its material and its local lighting (a shadow ray per light), handed
/// to `then`, whose result it returns. The material stays in the scene (moved out per pixel,
/// its copy, a `u8` among numbers, so a byte-wise `memcpy`, cost a fifth of a Cortex-M4F
/// frame), and a pixel's value leaves in a register, where the surface point returned through
/// memory was a `memcpy` of about 100 bytes, twice a pixel, in a software number type (7 % of
/// a Cortex-M3 `soft32` frame).
#[inline(never)]
pub(crate) fn primary_surface_then<N: Number, R, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
    cache: &mut ShadowCache,
    culling: &[ShadowCulling<'_, N>],
    then: impl FnOnce(&SurfacePoint<N>, &PreparedMaterial<N>, Lighting<N>, &mut Statistics, &mut ShadowCache) -> R,
) -> Option<R> {
    let ray = scene.camera.primary_ray(pixel)?;
    statistics.rays_traced += 1;
    let hit = nearest_hit_cached(scene, &ray, pixel, statistics, &mut cache.last_hit)?;
    statistics.rays_intersected += 1;
    let object = scene.objects.get(hit.object)?;
    // Normal to world space through the inverse transpose (the thesis used the forward
    // matrix, digest §11 B2), facing the viewer (seen from inside, a surface's inner side).
    let at = SurfacePoint::new(object.object_from_world.transposed_vector(hit.local_normal), &ray, hit.t, hit.object);
    let lighting = direct_lighting(scene, hit.object, at.point, at.normal, ray.direction, object.material.power, statistics, cache, culling);
    Some(then(&at, &object.material, lighting, statistics, cache))
}

/// Renders the scene in PGA mode: one palette index per pixel, rows top first, calling
/// `row_done` after each row.
pub fn render_pga<N, S, const MAX_OBJECTS: usize, O: Objects<N>>(scene: &Scene<N, MAX_OBJECTS, O>, sink: &mut S, statistics: &mut Statistics)
where
    N: Number,
    S: PixelSink<u8> + PixelSource<u8>,
{
    render_pga_rows(scene, sink, statistics, 0..scene.viewport().height())
}

/// How many corners an antialiased render keeps of a row ([`render_pga`], [`render_rgb`]): an
/// image up to 2,048 pixels wide shares every corner (6 KB of stack); a wider one traces the
/// corners beyond again.
pub const ANTIALIAS_ROW: usize = 2049;

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

/// Pixelbuffer's fill colour in PGA mode (the thesis's default `fillcolor`); the flood is its
/// complement, so the two always differ.
pub const PGA_FILL: u8 = 112;
/// Pixelbuffer's fill colour in RGB mode; the flood is its complement.
pub const RGB_FILL: [u8; 3] = [112, 0, 255];

/// Pixels read back per `read_row` call (a stack buffer; no row-sized buffer is needed).
const READ_CHUNK: usize = 32;

/// A mode's pixels: a surface's own (the thesis's shading) and the ray tree's node colours.
pub(crate) trait Mode<N>: NodeColours<N> {
    fn surface(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> Self::Pixel;
    /// The pixel of an antialiased mean (8-bit RGB).
    fn averaged(&self, colour: [u8; 3]) -> Self::Pixel;
}

/// PGA mode: a surface's palette index; a tree's node is its index's LUT colour, and a mixed
/// pixel the LUT entry nearest the mix (scene format, chapter 5).
pub(crate) struct PgaNodes<'a, N, const MAX_OBJECTS: usize, O> {
    pub scene: &'a Scene<N, MAX_OBJECTS, O>,
}

impl<N: Number, const MAX_OBJECTS: usize, O: Objects<N>> NodeColours<N> for PgaNodes<'_, N, MAX_OBJECTS, O> {
    type Pixel = u8;
    fn finish(&self, colour: [N; 3], _pixel: PixelPosition) -> u8 {
        let half = self.scene.constants.half;
        self.scene.palette.nearest(colour.map(|c| (c + half).floor_to_i32().clamp(0, 255) as u8))
    }
    fn local(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> [N; 3] {
        lut_colour(self.scene, self.surface(material, lighting, pixel))
    }
    fn background(&self) -> [N; 3] {
        lut_colour(self.scene, self.scene.background)
    }
}

#[cfg_attr(not(feature = "ray-tree"), allow(dead_code))]
fn lut_colour<N: Number, const MAX_OBJECTS: usize, O: Objects<N>>(scene: &Scene<N, MAX_OBJECTS, O>, index: u8) -> [N; 3] {
    scene.palette.entry(index).to_rgb888().map(|c| N::from_i32(i32::from(c)))
}

impl<N: Number, const MAX_OBJECTS: usize, O: Objects<N>> Mode<N> for PgaNodes<'_, N, MAX_OBJECTS, O> {
    fn surface(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> u8 {
        pga_index(material, lighting, &self.scene.constants, self.scene.dither, pixel)
    }
    fn averaged(&self, colour: [u8; 3]) -> u8 {
        self.scene.palette.nearest(colour)
    }
}

/// RGB mode: the channels' intensities, clamped and rounded (or dithered) once at the end.
pub(crate) struct RgbNodes<'a, N, const MAX_OBJECTS: usize, O> {
    pub scene: &'a Scene<N, MAX_OBJECTS, O>,
}

impl<N: Number, const MAX_OBJECTS: usize, O: Objects<N>> NodeColours<N> for RgbNodes<'_, N, MAX_OBJECTS, O> {
    type Pixel = Rgb888;
    fn finish(&self, colour: [N; 3], pixel: PixelPosition) -> Rgb888 {
        rgb_quantized(colour, &self.scene.constants, self.scene.dither, pixel)
    }
    fn local(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, _pixel: PixelPosition) -> [N; 3] {
        rgb_intensity(material, lighting, &self.scene.constants)
    }
    fn background(&self) -> [N; 3] {
        self.scene.background_rgb().map(|c| N::from_i32(i32::from(c)))
    }
}

impl<N: Number, const MAX_OBJECTS: usize, O: Objects<N>> Mode<N> for RgbNodes<'_, N, MAX_OBJECTS, O> {
    fn surface(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> Rgb888 {
        rgb_pixel(material, lighting, &self.scene.constants, self.scene.dither, pixel)
    }
    fn averaged(&self, colour: [u8; 3]) -> Rgb888 {
        colour
    }
}

/// One pixel: the primary hit's own shade, or, when the ray tree spawns rays from it, the
/// tree's mix (a tree at most `DEPTH` generations deep).
#[inline]
pub(crate) fn pixel_value<N, M, const MAX_OBJECTS: usize, O: Objects<N>, const DEPTH: usize>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    mode: &M,
    pixel: PixelPosition,
    statistics: &mut Statistics,
    cache: &mut ShadowCache,
    culling: &[ShadowCulling<'_, N>],
) -> Option<M::Pixel>
where
    N: Number,
    M: Mode<N>,
{
    primary_surface_then(scene, pixel, statistics, cache, culling, |at, material, lighting, statistics, cache| {
        #[cfg(feature = "ray-tree")]
        if scene.has_ray_tree() {
            let context = TreeContext { scene, colours: mode, pixel, culling };
            if let Some(mixed) = trace_tree::<N, M, MAX_OBJECTS, O, DEPTH>(&context, *at, mode.local(material, lighting, pixel), statistics, cache) {
                return mode.finish(mixed, pixel);
            }
        }
        #[cfg(not(feature = "ray-tree"))]
        let _ = (at, statistics, cache);
        mode.surface(material, lighting, pixel)
    })
}

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

/// Pixelbuffer's preprocess (`initpga` and `rendervolume`): flood the viewport, then fill
/// every object's extent octagon (its silhouette's rectangle cut by the two diagonal ranges,
/// computed when the scene was prepared), row span by row span, in integer arithmetic. With
/// the thesis's tuning, the thesis's fill: each 8-vertex volume projected and scan-converted. Public so a viewer can
/// record which pixels the fill marks (into a sink of its own, with its own two values).
pub fn fill_volumes<N, P, S, const MAX_OBJECTS: usize, O: Objects<N>>(scene: &Scene<N, MAX_OBJECTS, O>, sink: &mut S, fill: P, flood: P)
where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
{
    fill_volumes_rows(scene, sink, fill, flood, 0..scene.acceleration.screen().height)
}

/// [`fill_volumes`] within the image rows `rows` only.
pub fn fill_volumes_rows<N, P, S, const MAX_OBJECTS: usize, O: Objects<N>>(scene: &Scene<N, MAX_OBJECTS, O>, sink: &mut S, fill: P, flood: P, rows: Range<u16>)
where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
{
    let screen = scene.acceleration.screen();
    let width = screen.width;
    let rows = rows.start..rows.end.min(screen.height);
    if rows.is_empty() {
        return;
    }
    for row in rows.clone() {
        sink.mark_row(0, row, width, flood);
    }
    let acceleration = &scene.acceleration;
    if acceleration.tuning().tight_silhouettes || !crate::optimize::SILHOUETTES {
        // Each object's extent octagon, prepared with the other optimizations: integer spans,
        // no projection per frame.
        for index in 0..scene.objects.len() {
            let Some(extent) = acceleration.extent(index) else { continue };
            // Rows outside the extent first: the streamed render fills one row at a time, and
            // most objects miss it.
            if extent.last_row < rows.start || extent.first_row >= rows.end {
                continue;
            }
            let stadium = acceleration.stadium(index);
            for row in rows.clone() {
                let Some(span) = extent.row_span(row, screen.height) else { continue };
                // Narrowed by the silhouette's stadium: a thin oblique rod fills a band along it.
                let span = match stadium {
                    Some(stadium) => match stadium.block(span, (row, row)) {
                        Some((columns, _)) => columns,
                        None => continue,
                    },
                    None => span,
                };
                sink.mark_row(span.0, row, span.1 - span.0 + 1, fill);
            }
        }
        return;
    }
    // The thesis's fill: each object's 8-vertex volume projected and scan-converted.
    for object in scene.objects.iter() {
        let projected = match ObjectGeometry::new(object.primitive, &object.object_from_world) {
            Some(geometry) => screen.project_object(&geometry, false),
            None => Projected::Whole,
        };
        let points = match projected {
            Projected::Points(points) => points,
            Projected::Invisible => continue,
            Projected::Whole => {
                // No projection (the eye in or at the volume, or rays along the view plane): all.
                for row in rows.clone() {
                    sink.mark_row(0, row, width, fill);
                }
                continue;
            }
        };
        let extent = Extent::of(screen, &projected);
        if extent.is_empty() {
            continue;
        }
        for row in extent.first_row.max(rows.start)..=extent.last_row.min(rows.end - 1) {
            if let Some((first, last)) = hull_span(&points, row, width) {
                sink.mark_row(first, row, last - first + 1, fill);
            }
        }
    }
}

/// Runs `body` with the per-render shadow tables, one per light: for a point light each
/// object's cone of directions from the light, and which objects may shadow which (on the
/// stack: for `f32` about 60 bytes per object and light while a table is built, 32 while `body`
/// runs). Both are built in the number type, in work linear in the objects and their
/// overlapping pairs (`optimize::shadow::blocker_table`). Without the `acceleration-tables`
/// feature there are none.
#[cfg(feature = "acceleration-tables")]
pub(crate) fn with_shadow_culling<N: Number, R, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    let mut light_cones = [DirectionChord::ALWAYS; MAX_OBJECTS];
    let mut blockers = [BlockerSet::EMPTY; MAX_OBJECTS];
    let culls = scene.shadows && scene.acceleration.culls_shadows();
    let count = if culls { scene.objects.len().min(MAX_OBJECTS) } else { 0 };
    if culls {
        build_shadow_tables(scene, scene.light, count, &mut light_cones, &mut blockers);
    }
    let first = culling_of(scene.light, count, &light_cones, &blockers);
    if culls && !scene.more_lights.is_empty() {
        return with_more_lights_culling(scene, count, first, body);
    }
    body(&[first])
}

/// The tables of the lights after the first, out of line so that a scene with one light
/// keeps none of their stack.
#[cfg(feature = "acceleration-tables")]
#[inline(never)]
fn with_more_lights_culling<N: Number, R, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    count: usize,
    first: ShadowCulling<'_, N>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    const MORE: usize = MAX_LIGHTS - 1;
    let mut light_cones = [[DirectionChord::ALWAYS; MAX_OBJECTS]; MORE];
    let mut blockers = [[BlockerSet::EMPTY; MAX_OBJECTS]; MORE];
    for ((source, cones), sets) in scene.more_lights.iter().zip(light_cones.iter_mut()).zip(blockers.iter_mut()) {
        build_shadow_tables(scene, source.light, count, cones, sets);
    }
    let mut culling = [ShadowCulling::default(); MAX_LIGHTS];
    culling[0] = first;
    for (((slot, source), cones), sets) in culling.iter_mut().skip(1).zip(scene.more_lights.iter()).zip(light_cones.iter()).zip(blockers.iter()) {
        *slot = culling_of(source.light, count, cones, sets);
    }
    body(culling.get(..=scene.more_lights.len()).unwrap_or(&[]))
}

/// The culling of one light from its tables (only a point light has cones).
#[cfg(feature = "acceleration-tables")]
fn culling_of<'a, N: Number>(light: PreparedLight<N>, count: usize, light_cones: &'a [DirectionChord<N>], blockers: &'a [BlockerSet]) -> ShadowCulling<'a, N> {
    let cone_count = if matches!(light, PreparedLight::Point(_)) { count } else { 0 };
    ShadowCulling { light_cones: light_cones.get(..cone_count).unwrap_or(&[]), blockers: blockers.get(..count).unwrap_or(&[]) }
}

/// The footprints and the blocker table of one light, out of line: the footprints (40 bytes an
/// object in `f32`) are off the stack before the render's frames are on it.
#[cfg(feature = "acceleration-tables")]
#[inline(never)]
fn build_shadow_tables<N: Number, const MAX_OBJECTS: usize, O: Objects<N>>(
    scene: &Scene<N, MAX_OBJECTS, O>,
    light: PreparedLight<N>,
    count: usize,
    light_cones: &mut [DirectionChord<N>; MAX_OBJECTS],
    blockers: &mut [BlockerSet; MAX_OBJECTS],
) {
    let light = match light {
        PreparedLight::Point(position) => LightPosition::Point(position),
        PreparedLight::Direction(direction) => LightPosition::Direction(direction),
    };
    // Each footprint's chord goes straight to the render's table; only the reaches are kept
    // for the sweep (6 numbers an object).
    let mut reaches = [LightReach::always(); MAX_OBJECTS];
    for (index, (cone, reach)) in light_cones.iter_mut().zip(reaches.iter_mut()).enumerate().take(count) {
        let footprint = scene.acceleration.light_footprint(index, light);
        *cone = footprint.chord;
        *reach = footprint.reach;
    }
    let mut order = [0u16; MAX_OBJECTS];
    blocker_table(reaches.get(..count).unwrap_or(&[]), &mut order, blockers);
}

#[cfg(not(feature = "acceleration-tables"))]
pub(crate) fn with_shadow_culling<N: Number, R, const MAX_OBJECTS: usize, O: Objects<N>>(
    _scene: &Scene<N, MAX_OBJECTS, O>,
    body: impl FnOnce(&[ShadowCulling<'_, N>]) -> R,
) -> R {
    body(&[])
}
