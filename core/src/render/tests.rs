//! Centre-pixel shades worked out by hand (digest §6.2–6.3).

use super::*;
use crate::geometry::Vector3;
use crate::pixel::MockSink;
use crate::model::{Light, Material, ObjectDescription, Primitive, Projection, SceneDescription, Viewport, Window};
use crate::scene::Scene;

/// A 5x5 image of the unit sphere seen along −z, centre pixel (2, 2) on the sphere's pole.
fn sphere_scene(material: Material, light: Light) -> SceneDescription<4> {
    let mut scene = SceneDescription::<4> {
        viewport: Viewport { x1: 0, x2: 4, y1: 0, y2: 4 },
        window: Window { x1: -2.0, x2: 2.0, y1: -2.0, y2: 2.0 },
        view_plane: 10.0,
        projection: Projection::Parallel { direction: [0.0, 0.0, -1.0] },
        light,
        background: 7,
        ..Default::default()
    };
    let mut sphere = ObjectDescription::new(Primitive::Sphere, 1);
    sphere.material = material;
    scene.objects.push(sphere).unwrap();
    scene
}

fn centre_pixel(description: &SceneDescription<4>) -> (u8, u8) {
    let scene = Scene::<f64, 4>::prepare(description).unwrap();
    let mut sink = MockSink::<u8, 5, 5>::new(0);
    render(&scene, Pga, Whole, &mut sink, &mut Statistics::default());
    (sink.pixels[2][2], sink.pixels[0][0])
}

fn matte(colour: u8, ka: f64, kd: f64, ks: f64, pwr: f64) -> Material {
    Material { colour, ka, kd, ks, pwr, rnd: 0.0, cmy: [0.3; 3], ..Material::default() }
}

const SIXTY_DEGREES: [f64; 3] = [0.0, 0.866_025_403_784_438_6, 0.5];

#[test]
fn light_along_the_normal_gives_ambient_plus_full_diffuse() {
    // 15·(kd·1 + ka·Ia) = 15·(0.5 + 0.2) = 10.5, rounded up to 11; index 16·3 + 11.
    let scene = sphere_scene(matte(3, 1.0, 0.5, 0.0, 20.0), Light::Direction([0.0, 0.0, 1.0]));
    assert_eq!(centre_pixel(&scene), (59, 7));
}

#[test]
fn light_at_sixty_degrees_halves_the_diffuse_term() {
    // diff = cos 60° = 0.5: 15·(0.6·0.5 + 0.2) = 7.5 -> 8.
    let scene = sphere_scene(matte(0, 1.0, 0.6, 0.0, 20.0), Light::Direction(SIXTY_DEGREES));
    assert_eq!(centre_pixel(&scene).0, 8);
}

#[test]
fn specular_uses_the_halfway_vector() {
    // H = normalize(L − D) = (0, 0.5, 0.866); N·H = 0.866; squared 0.75; 15·0.5·0.75 = 5.625 -> 6.
    let scene = sphere_scene(matte(0, 0.0, 0.0, 0.5, 2.0), Light::Direction(SIXTY_DEGREES));
    assert_eq!(centre_pixel(&scene).0, 6);
}

#[test]
fn highlight_clips_at_shade_15() {
    // The defaults: 15·(0.6 + 0.4 + 0.2) = 18 plus noise, clipped to 14.9, rounds to 15.
    let scene = sphere_scene(Material::default(), Light::Direction([0.0, 0.0, 1.0]));
    assert_eq!(centre_pixel(&scene).0, 15);
}

#[test]
fn shadow_rays_stop_at_a_point_light() {
    // A small sphere at z = 5 above the pole, the light at z = 8: blocked; with the blocker
    // moved beyond the light: not blocked.
    let mut scene = sphere_scene(matte(1, 1.0, 0.6, 0.3, 20.0), Light::Point([0.0, 0.0, 8.0]));
    let mut blocker = ObjectDescription::new(Primitive::Sphere, 2);
    blocker.world_from_object.scale([0.1, 0.1, 0.1]);
    blocker.world_from_object.translate([0.0, 0.0, 5.0]);
    scene.objects.push(blocker).unwrap();
    let pole = Vector3::new(0.0, 0.0, 1.0);
    let up = Vector3::new(0.0, 0.0, 1.0);
    let mut statistics = Statistics::default();
    let prepared = Scene::<f64, 4>::prepare(&scene).unwrap();
    assert!(in_shadow(&prepared, 0, pole, up, 7.0, &mut statistics));
    assert_eq!((statistics.shadow_rays, statistics.shadow_tests), (1, 1));
    scene.objects[1].world_from_object.translate([0.0, 0.0, 10.0]);
    let prepared = Scene::<f64, 4>::prepare(&scene).unwrap();
    assert!(!in_shadow(&prepared, 0, pole, up, 7.0, &mut statistics));
}

#[test]
fn shadowed_centre_pixel_is_ambient_only() {
    // Light to the side at 60°; a blocker on the shadow ray but off the primary ray.
    let mut scene = sphere_scene(matte(1, 1.0, 0.6, 0.3, 20.0), Light::Direction(SIXTY_DEGREES));
    scene.shadows = true;
    let mut blocker = ObjectDescription::new(Primitive::Cube, 2);
    blocker.world_from_object.translate([-0.5, 2.0, 2.5]);
    scene.objects.push(blocker).unwrap();
    assert_eq!(centre_pixel(&scene).0, 16 + 3);
    scene.shadows = false;
    // Unshadowed: 15·(0.6·0.5 + 0.3·(N·H)^20 + 0.2) with N·H = 0.866: 7.5 + 0.2536·... = 15·0.5533 = 8.30 -> 8.
    assert_eq!(centre_pixel(&scene).0, 16 + 8);
}

#[test]
fn rgb_mode_adds_light_and_reflects_one_minus_cmy() {
    let mut material = matte(0, 1.0, 0.5, 0.0, 20.0);
    material.cmy = [0.0, 0.5, 1.0];
    let description = sphere_scene(material, Light::Direction([0.0, 0.0, 1.0]));
    let scene = Scene::<f64, 4>::prepare(&description).unwrap();
    let mut sink = MockSink::<[u8; 3], 5, 5>::new([0; 3]);
    render(&scene, Rgb, Whole, &mut sink, &mut Statistics::default());
    // 255·(0.5 + 0.2)·ρ with ρ = (1, 0.5, 0): 178.5 -> 179 (clipped at 254.9 first), 89.25 -> 89, 0.
    assert_eq!(sink.pixels[2][2], [179, 89, 0]);
    // Background through the look-up table: index 7 of the grey default is (7,7,7) -> 119.
    assert_eq!(sink.pixels[0][0], [119, 119, 119]);
}

#[test]
fn statistics_count_pixels_rays_and_tests() {
    let mut description = sphere_scene(Material::default(), Light::Direction([0.0, 0.0, 1.0]));
    // Unoptimized: every pixel gets a ray and every ray tests the one object.
    description.optimizations = crate::model::Optimizations::NONE;
    let scene = Scene::<f64, 4>::prepare(&description).unwrap();
    let mut sink = MockSink::<u8, 5, 5>::new(0);
    let mut statistics = Statistics::default();
    render(&scene, Pga, Whole, &mut sink, &mut statistics);
    // Pixels at distance ≤ 1 from the centre hit: the centre and its 4 neighbours.
    assert_eq!(statistics.pixels, 25);
    assert_eq!(statistics.rays_traced, 25);
    assert_eq!(statistics.rays_intersected, 5);
    assert_eq!(statistics.ro_tests, 25);
    assert_eq!(sink.rows_done, 5);
}

/// Bands rendered one by one (as threads do) give the whole render's pixels, with Pixelbuffer
/// on, and the band's sink sees only the band's rows.
#[test]
fn bands_render_the_same_pixels_as_the_whole_image() {
    let mut description = sphere_scene(matte(3, 1.0, 0.5, 0.3, 20.0), Light::Point([3.0, 4.0, 10.0]));
    description.optimizations = crate::model::Optimizations::ALL;
    let scene = Scene::<f64, 4>::prepare(&description).unwrap();
    let mut whole = MockSink::<u8, 5, 5>::new(0);
    render(&scene, Pga, Whole, &mut whole, &mut Statistics::default());
    let mut banded = MockSink::<u8, 5, 5>::new(0);
    for (first, end) in [(0, 2), (2, 3), (3, 3), (3, 5)] {
        let mut band = MockSink::<u8, 5, 5>::new(0);
        let mut statistics = Statistics::default();
        render(&scene, Pga, Rows(first..end), &mut band, &mut statistics);
        assert_eq!(statistics.pixels, 5 * u64::from(end - first));
        for row in 0..5 {
            if (first..end).contains(&row) {
                banded.pixels[usize::from(row)] = band.pixels[usize::from(row)];
            } else {
                assert_eq!(band.pixels[usize::from(row)], [0; 5], "row {row} outside the band {first}..{end}");
            }
        }
    }
    assert_eq!(banded.pixels, whole.pixels);
}

