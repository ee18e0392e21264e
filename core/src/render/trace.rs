//! Tracing a whole image, top row first (digest §3.4), into a [`PixelSink`].

use super::{in_shadow, nearest_hit, Statistics};
use crate::camera::PixelPosition;
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
    let Some(ray) = scene.camera.primary_ray(pixel) else { return ShadedPixel::Background };
    statistics.rays_traced += 1;
    let Some(hit) = nearest_hit(scene, &ray, pixel, statistics) else { return ShadedPixel::Background };
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
            (offset.normalized().unwrap_or(normal), distance)
        }
        PreparedLight::Direction(direction) => (direction, N::MAX),
    };
    // A surface facing away from the light is unlit with or without a shadow ray.
    let faces_light = normal.dot(to_light) > N::ZERO;
    let shadowed = scene.shadows && faces_light && in_shadow(scene, hit.object, point, to_light, light_distance, statistics);
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
    render(scene, sink, statistics, scene.background, |material, lighting, pixel| {
        pga_index(material, lighting, &scene.constants, scene.dither, pixel)
    })
}

/// Renders the scene in RGB mode (see `shading::rgb` for how it differs from the thesis).
pub fn render_rgb<N, S, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>, sink: &mut S, statistics: &mut Statistics)
where
    N: Number,
    S: PixelSink<Rgb888> + PixelSource<Rgb888>,
{
    render(scene, sink, statistics, scene.background_rgb(), |material, lighting, pixel| {
        rgb_pixel(material, lighting, &scene.constants, scene.dither, pixel)
    })
}

fn render<N, P, S, const MAX_OBJECTS: usize>(
    scene: &Scene<N, MAX_OBJECTS>,
    sink: &mut S,
    statistics: &mut Statistics,
    background: P,
    colour: impl Fn(&PreparedMaterial<N>, Lighting<N>, PixelPosition) -> P,
) where
    N: Number,
    P: Copy,
    S: PixelSink<P> + PixelSource<P>,
{
    let camera = &scene.camera;
    for row in 0..camera.height() {
        for column in 0..camera.width() {
            let pixel = camera.pixel(column, row);
            statistics.pixels += 1;
            let value = match shade_pixel(scene, pixel, statistics) {
                ShadedPixel::Background => background,
                ShadedPixel::Surface { material, lighting } => colour(&material, lighting, pixel),
            };
            sink.set_pixel(column, row, value);
        }
        sink.row_done(row);
    }
}
