//! Tracing a whole image, top row first (digest §3.4), into a [`PixelSink`].

use core::ops::Range;

use super::shadow::{in_shadow_culled, shadow_origin, ShadowCache, ShadowCulling};
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
use crate::scene::{PreparedLight, PreparedMaterial, Scene};
use crate::shading::{lighting, pga_index, rgb_pixel, Lighting};

/// What a traced pixel saw: nothing, or an object's material lit by `lighting`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadedPixel<N> {
    Background,
    Surface { material: PreparedMaterial<N>, lighting: Lighting<N> },
}

/// Traces one pixel's primary ray and, for a hit, its shadow ray, and evaluates the lighting.
pub fn shade_pixel<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
) -> ShadedPixel<N> {
    shade_pixel_cached(scene, pixel, statistics, &mut ShadowCache::default(), &ShadowCulling::default())
}

pub(crate) fn shade_pixel_cached<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
    cache: &mut ShadowCache,
    culling: &ShadowCulling<'_, N>,
) -> ShadedPixel<N> {
    let Some(ray) = scene.camera.primary_ray(pixel) else { return ShadedPixel::Background };
    statistics.rays_traced += 1;
    let Some(hit) = nearest_hit_cached(scene, &ray, pixel, statistics, &mut cache.last_hit) else { return ShadedPixel::Background };
    statistics.rays_intersected += 1;
    let Some(object) = scene.objects.get(hit.object) else { return ShadedPixel::Background };
    // Normal to world space through the inverse transpose (the thesis used the forward
    // matrix, digest §11 B2), facing the viewer (seen from inside, a surface's inner side).
    let mut normal = object.object_from_world.transposed_vector(hit.local_normal).normalized().unwrap_or(-ray.direction);
    if normal.dot(ray.direction) > N::ZERO {
        normal = -normal;
    }
    let point = ray.at(hit.t);
    let (to_light, light_distance) = match scene.light {
        PreparedLight::Point(position) => {
            let offset = position - point;
            let distance = offset.length();
            // As `normalized()`, without computing the length twice.
            let direction = N::ONE.checked_div(distance).map_or(normal, |reciprocal| offset * reciprocal);
            (direction, distance)
        }
        PreparedLight::Direction(direction) => (direction, N::MAX),
    };
    // A surface facing away from the light is unlit with or without a shadow ray.
    let faces_light = normal.dot(to_light) > N::ZERO;
    let shadowed = scene.shadows && faces_light && in_shadow_culled(scene, hit.object, shadow_origin(point, normal), to_light, light_distance, statistics, cache, culling);
    ShadedPixel::Surface {
        material: object.material,
        lighting: lighting(normal, to_light, ray.direction, object.material.power, shadowed),
    }
}

/// Renders the scene in PGA mode: one palette index per pixel, rows top first, calling
/// `row_done` after each row.
pub fn render_pga<N, S, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>, sink: &mut S, statistics: &mut Statistics)
where
    N: Number,
    S: PixelSink<u8> + PixelSource<u8>,
{
    render_pga_rows(scene, sink, statistics, 0..scene.camera.height())
}

/// [`render_pga`] of the image rows `rows` only (a band, for one of several threads): the
/// sink receives only those rows. Every pixel's value equals the whole render's; the
/// statistics are the band's (the hit and shadow caches start empty at its first row).
pub fn render_pga_rows<N, S, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>, sink: &mut S, statistics: &mut Statistics, rows: Range<u16>)
where
    N: Number,
    S: PixelSink<u8> + PixelSource<u8>,
{
    render(scene, sink, statistics, rows, scene.background, (PGA_FILL, PGA_FILL ^ 0xFF), |material, lighting, pixel| {
        pga_index(material, lighting, &scene.constants, scene.dither, pixel)
    })
}

/// Renders the scene in RGB mode (see `shading::rgb` for how it differs from the thesis).
pub fn render_rgb<N, S, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>, sink: &mut S, statistics: &mut Statistics)
where
    N: Number,
    S: PixelSink<Rgb888> + PixelSource<Rgb888>,
{
    render_rgb_rows(scene, sink, statistics, 0..scene.camera.height())
}

/// [`render_rgb`] of the image rows `rows` only (see [`render_pga_rows`]).
pub fn render_rgb_rows<N, S, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>, sink: &mut S, statistics: &mut Statistics, rows: Range<u16>)
where
    N: Number,
    S: PixelSink<Rgb888> + PixelSource<Rgb888>,
{
    render(scene, sink, statistics, rows, scene.background_rgb(), (RGB_FILL, RGB_FILL.map(|c| c ^ 0xFF)), |material, lighting, pixel| {
        rgb_pixel(material, lighting, &scene.constants, scene.dither, pixel)
    })
}

/// Pixelbuffer's fill colour in PGA mode (the thesis's default `fillcolor`); the flood is its
/// complement, so the two always differ.
pub const PGA_FILL: u8 = 112;
/// Pixelbuffer's fill colour in RGB mode; the flood is its complement.
pub const RGB_FILL: [u8; 3] = [112, 0, 255];

/// Pixels read back per `read_row` call (a stack buffer; no row-sized buffer is needed).
const READ_CHUNK: usize = 32;

fn render<N, P, S, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    sink: &mut S,
    statistics: &mut Statistics,
    rows: Range<u16>,
    background: P,
    (fill, flood): (P, P),
    colour: impl Fn(&PreparedMaterial<N>, Lighting<N>, PixelPosition) -> P,
) where
    N: Number,
    P: Copy + PartialEq,
    S: PixelSink<P> + PixelSource<P>,
{
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
            let value = match shade_pixel_cached(scene, pixel, statistics, &mut cache, culling) {
                ShadedPixel::Background => background,
                ShadedPixel::Surface { material, lighting } => colour(&material, lighting, pixel),
            };
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
pub fn fill_volumes<N, P, S, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>, sink: &mut S, fill: P, flood: P)
where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
{
    fill_volumes_rows(scene, sink, fill, flood, 0..scene.acceleration.screen().height)
}

/// [`fill_volumes`] within the image rows `rows` only.
pub fn fill_volumes_rows<N, P, S, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>, sink: &mut S, fill: P, flood: P, rows: Range<u16>)
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

/// Runs `body` with the per-render shadow tables: for a point light each object's cone of
/// directions from the light, and which objects may shadow which (on the stack: for `f32`
/// about 60 bytes per object while the table is built, 32 while `body` runs). Both are built
/// in the number type, in work linear in the objects and their overlapping pairs
/// (`optimize::shadow::blocker_table`). Without the `acceleration-tables` feature there are none.
#[cfg(feature = "acceleration-tables")]
pub(crate) fn with_shadow_culling<N: Number, R, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    body: impl FnOnce(&ShadowCulling<'_, N>) -> R,
) -> R {
    let mut light_cones = [DirectionChord::ALWAYS; MAX_OBJECTS];
    let mut blockers = [BlockerSet::EMPTY; MAX_OBJECTS];
    let mut count = 0;
    if scene.shadows && scene.acceleration.culls_shadows() {
        count = scene.objects.len().min(MAX_OBJECTS);
        build_shadow_tables(scene, count, &mut light_cones, &mut blockers);
    }
    let cone_count = if matches!(scene.light, PreparedLight::Point(_)) { count } else { 0 };
    body(&ShadowCulling { light_cones: light_cones.get(..cone_count).unwrap_or(&[]), blockers: blockers.get(..count).unwrap_or(&[]) })
}

/// The footprints and the blocker table, out of line: the footprints (40 bytes an object in
/// `f32`) are off the stack before the render's frames are on it.
#[cfg(feature = "acceleration-tables")]
#[inline(never)]
fn build_shadow_tables<N: Number, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    count: usize,
    light_cones: &mut [DirectionChord<N>; MAX_OBJECTS],
    blockers: &mut [BlockerSet; MAX_OBJECTS],
) {
    let light = match scene.light {
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
pub(crate) fn with_shadow_culling<N: Number, R, const MAX_OBJECTS: usize>(
    _scene: &Scene<N, MAX_OBJECTS>,
    body: impl FnOnce(&ShadowCulling<'_, N>) -> R,
) -> R {
    body(&ShadowCulling::default())
}
