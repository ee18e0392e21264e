//! One pixel (RTRACE.C `raycast`): the primary ray's nearest hit, its local lighting with a
//! shadow ray per light, and, when the ray tree spawns rays from it, the tree's mix.

use super::direct_lighting::direct_lighting;
use super::mode::Mode;
use super::primary::nearest_hit_cached;
#[cfg(feature = "ray-tree")]
use super::ray_tree::{trace_tree, TreeContext};
use super::shadow_ray::{ShadowCache, ShadowCulling};
use super::surface::SurfacePoint;
use super::Statistics;
use crate::camera::PixelPosition;
use crate::model::PreparedMaterial;
use crate::number::Number;
use crate::config::Config;
use crate::scene::Prepared;
use crate::light::Lighting;

/// What a traced pixel saw: nothing, or an object's material lit by `lighting`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadedPixel<N> {
    Background,
    Surface { material: PreparedMaterial<N>, lighting: Lighting<N> },
}

/// Traces one pixel's primary ray and, for a hit, its shadow ray, and evaluates the lighting.
pub fn shade_pixel<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
) -> ShadedPixel<N> {
    shade_pixel_cached(scene, pixel, statistics, &mut ShadowCache::default(), &[])
}

fn shade_pixel_cached<N: Number, C: Config<Number = N>>(
    scene: &Prepared<C>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
    culling: &[ShadowCulling<'_, N, C::Index>],
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
pub(crate) fn primary_surface_then<N: Number, R, C: Config<Number = N>>(
    scene: &Prepared<C>,
    pixel: PixelPosition,
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
    culling: &[ShadowCulling<'_, N, C::Index>],
    then: impl FnOnce(&SurfacePoint<N>, &PreparedMaterial<N>, Lighting<N>, &mut Statistics, &mut ShadowCache<C::Index>) -> R,
) -> Option<R> {
    let ray = scene.camera.primary_ray(pixel)?;
    statistics.rays_traced += 1;
    let hit = nearest_hit_cached(scene, &ray, pixel, statistics, &mut cache.last_hit)?;
    statistics.rays_intersected += 1;
    let object = super::intersect::surface_of(scene, &hit)?;
    // Normal to world space through the inverse transpose (the thesis used the forward
    // matrix, digest §11 B2), facing the viewer (seen from inside, a surface's inner side).
    let at = SurfacePoint::new(object.object_from_world.transposed_vector(hit.local_normal), &ray, hit.t, hit.object);
    let lighting = direct_lighting(scene, hit.object, at.lit_point(object, &ray, hit.t), at.normal, ray.direction, object.material.power, statistics, cache, culling);
    Some(then(&at, &object.material, lighting, statistics, cache))
}

/// One pixel: the primary hit's own shade, or, when the ray tree spawns rays from it, the
/// tree's mix (a tree at most `DEPTH` generations deep).
#[inline]
pub(crate) fn pixel_value<N, M, C: Config<Number = N>>(
    scene: &Prepared<C>,
    mode: &M,
    pixel: PixelPosition,
    statistics: &mut Statistics,
    cache: &mut ShadowCache<C::Index>,
    culling: &[ShadowCulling<'_, N, C::Index>],
) -> Option<M::Pixel>
where
    N: Number,
    M: Mode<N>,
{
    primary_surface_then(scene, pixel, statistics, cache, culling, |at, material, lighting, statistics, cache| {
        #[cfg(feature = "ray-tree")]
        if scene.has_ray_tree() {
            let context = TreeContext { scene, colours: mode, pixel, culling };
            if let Some(mixed) = trace_tree::<N, M, C>(&context, *at, mode.local(material, lighting, pixel), statistics, cache) {
                return mode.finish(mixed, pixel);
            }
        }
        #[cfg(not(feature = "ray-tree"))]
        let _ = (at, statistics, cache);
        mode.surface(material, lighting, pixel)
    })
}

