//! The passes' order, blocks and counts, on a mock sink.

use super::*;
use crate::model::Rgb888;
use crate::scene::Scene;
use crate::pixel::MockSink;
use crate::render::{Pass, Pga, Progressive, Rgb, Whole, render};
use crate::model::{Light, Material, ObjectDescription, Optimizations, Primitive, Projection, SceneDescription, Viewport, Window};

const W: usize = 21;
const H: usize = 13;

/// A 21x13 image (neither side a multiple of 8, so the last blocks are clipped) of a rough
/// shaded sphere and a cube partly off the image: many distinct values, and background.
fn scene(optimizations: Optimizations) -> Scene<f64, 4> {
    let mut description = SceneDescription::<4> {
        viewport: Viewport { x1: 0, x2: W as u16 - 1, y1: 0, y2: H as u16 - 1 },
        window: Window { x1: -2.2, x2: 2.2, y1: -1.4, y2: 1.4 },
        view_plane: 10.0,
        projection: Projection::Parallel { direction: [0.0, 0.0, -1.0] },
        light: Light::Direction([0.3, 0.5, 0.8]),
        background: 7,
        optimizations,
        ..Default::default()
    };
    let mut sphere = ObjectDescription::new(Primitive::Sphere, 1);
    sphere.material = Material { colour: 3, ka: 0.3, kd: 0.6, ks: 0.4, pwr: 10.0, rnd: 0.8, cmy: [0.3; 3], ..Material::default() };
    description.objects.push(sphere).unwrap();
    let mut cube = ObjectDescription::new(Primitive::Cube, 2);
    cube.world_from_object.translate([1.2, -1.5, 0.0]);
    description.objects.push(cube).unwrap();
    Scene::prepare(&description).unwrap()
}

fn normal_render(scene: &Scene<f64, 4>) -> (MockSink<u8, W, H>, Statistics) {
    let mut sink = MockSink::new(0);
    let mut statistics = Statistics::default();
    render(scene, Pga, Whole, &mut sink, &mut statistics);
    (sink, statistics)
}

/// Pixels of pass `pass`.
fn pass_pixels(pass: usize) -> u64 {
    (0..H as u16).flat_map(|y| (0..W as u16).map(move |x| (x, y))).filter(|&(x, y)| traced_in_pass(pass, x, y)).count() as u64
}

#[test]
fn every_pixel_is_traced_in_exactly_one_pass() {
    for y in 0..40u16 {
        for x in 0..40u16 {
            let passes: usize = (0..PASSES).filter(|&pass| traced_in_pass(pass, x, y)).count();
            assert_eq!(passes, 1, "pixel ({x}, {y})");
        }
    }
    assert!(traced_in_pass(0, 16, 8) && traced_in_pass(1, 4, 8) && traced_in_pass(2, 2, 6) && traced_in_pass(3, 5, 0));
    assert!(!traced_in_pass(1, 8, 8) && !traced_in_pass(4, 0, 0));
}

#[test]
fn each_pass_shows_every_block_in_its_corner_pixels_final_value() {
    let scene = scene(Optimizations::NONE);
    let (reference, _) = normal_render(&scene);
    let mut seen = [false; 256];
    reference.pixels.iter().flatten().for_each(|value| seen[usize::from(*value)] = true);
    let distinct = seen.iter().filter(|seen| **seen).count();
    assert!(distinct > 8, "the test scene has only {distinct} values");
    let mut sink = MockSink::<u8, W, H>::new(0);
    for (pass, &size) in PASS_SIZES.iter().enumerate() {
        let writes_before = sink.writes;
        let mut statistics = Statistics::default();
        render(&scene, Pga, Pass(pass), &mut sink, &mut statistics);
        let s = usize::from(size);
        for y in 0..H {
            for x in 0..W {
                let corner = reference.pixels[y - y % s][x - x % s];
                assert_eq!(sink.pixels[y][x], corner, "after pass {pass} (size {size}), pixel ({x}, {y})");
            }
        }
        // Parallel rays: every pixel of the pass gets one, and nothing else does.
        assert_eq!(statistics.pixels, pass_pixels(pass));
        assert_eq!(statistics.rays_traced, pass_pixels(pass), "pass {pass}");
        // The blocks cover the pixels no earlier pass traced, each once: all pixels in the
        // first pass, then all but the earlier passes' blocks of this size.
        let untouched = if pass == 0 { 0 } else { (0..H).flat_map(|y| (0..W).map(move |x| (x, y))).filter(|&(x, y)| (x - x % s) % (2 * s) == 0 && (y - y % s) % (2 * s) == 0).count() };
        assert_eq!(sink.writes - writes_before, (W * H - untouched) as u32, "writes in pass {pass}");
        assert_eq!(sink.out_of_bounds, 0);
    }
    assert_eq!(sink.pixels, reference.pixels);
    assert_eq!(sink.rows_done, (PASSES * H) as u32);
}

#[test]
fn every_pixel_is_last_written_in_its_own_pass() {
    let scene = scene(Optimizations::ALL);
    let (reference, normal) = normal_render(&scene);
    let mut sink = MockSink::<u8, W, H>::new(0);
    let mut statistics = PassStatistics::default();
    render(&scene, Pga, Progressive, &mut sink, &mut statistics);
    assert_eq!(sink.pixels, reference.pixels);
    // The writes' numbers at which each pass ended, from the block sizes.
    let mut ends = [0u32; PASSES];
    let mut written = 0;
    for (pass, end) in ends.iter_mut().enumerate() {
        let s = usize::from(PASS_SIZES[pass]);
        written += (0..H).flat_map(|y| (0..W).map(move |x| (x, y))).filter(|&(x, y)| pass == 0 || (x - x % s) % (2 * s) != 0 || (y - y % s) % (2 * s) != 0).count() as u32;
        *end = written;
    }
    assert_eq!(sink.writes, ends[PASSES - 1]);
    for y in 0..H {
        for x in 0..W {
            let last = sink.last_write[y][x];
            let pass = ends.iter().position(|end| last <= *end).unwrap();
            assert!(last > if pass == 0 { 0 } else { ends[pass - 1] });
            assert!(traced_in_pass(pass, x as u16, y as u16), "pixel ({x}, {y}) last written in pass {pass}");
        }
    }
    // Per pass: the pass's pixels; in all, the normal render's pixels and rays (Pixelbuffer's
    // coverage test skips the same pixels).
    for (pass, counts) in statistics.passes.iter().enumerate() {
        assert_eq!(counts.pixels, pass_pixels(pass));
        assert!(counts.rays_traced <= counts.pixels);
    }
    let total = statistics.total();
    assert_eq!(total.pixels, normal.pixels);
    assert_eq!(total.rays_traced, normal.rays_traced);
    assert_eq!(total.rays_intersected, normal.rays_intersected);
    assert!(total.rays_traced < total.pixels, "Pixelbuffer skipped no pixel: {total:?}");
}

#[test]
fn pixelbuffer_coverage_traces_the_pixels_the_normal_render_traces() {
    for optimizations in Optimizations::combinations() {
        let scene = scene(optimizations);
        let (reference, normal) = normal_render(&scene);
        let mut sink = MockSink::<u8, W, H>::new(0);
        let mut statistics = PassStatistics::default();
        render(&scene, Pga, Progressive, &mut sink, &mut statistics);
        assert_eq!(sink.pixels, reference.pixels, "{optimizations:?}");
        assert_eq!(statistics.total().rays_traced, normal.rays_traced, "{optimizations:?}");
    }
}

#[test]
fn rgb_mode_ends_with_the_normal_image() {
    let scene = scene(Optimizations::ALL);
    let mut reference = MockSink::<Rgb888, W, H>::new([0; 3]);
    crate::render::render(&scene, crate::render::Rgb, crate::render::Whole, &mut reference, &mut Statistics::default());
    let mut sink = MockSink::<Rgb888, W, H>::new([0; 3]);
    let mut statistics = PassStatistics::default();
    render(&scene, Rgb, Progressive, &mut sink, &mut statistics);
    assert_eq!(sink.pixels, reference.pixels);
    // After the first pass alone, the block corners' colours.
    let mut first = MockSink::<Rgb888, W, H>::new([0; 3]);
    render(&scene, Rgb, Pass(0), &mut first, &mut Statistics::default());
    assert_eq!(first.pixels[12][20], reference.pixels[8][16]);
    assert_eq!(first.pixels[5][3], reference.pixels[0][0]);
}
