//! Progressive display (issue 10, item 5): the coarse-to-fine render's final image is
//! byte-identical to the normal render on both thesis scenes under every one of the 16
//! optimization combinations, in f64 and f32, PGA and RGB mode; each pass traces its own
//! pixels, and the passes together trace exactly the rays the normal render traces.

use microtrace::number::Number;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{PASSES, PassStatistics, Pga, Progressive, Rgb, Statistics, Whole, render, traced_in_pass};
use microtrace::model::{Optimizations, SceneDescription};
use microtrace::scene::Scene;

const CAPACITY: usize = 64;

fn load(name: &str) -> SceneDescription<CAPACITY> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/").to_owned() + name;
    microtrace::parser::parse::<CAPACITY>(&std::fs::read(&path).unwrap()).unwrap_or_else(|error| panic!("{path}: {error}"))
}

/// The pixels each pass traces in a `width` x `height` image.
fn pass_pixels(width: u16, height: u16) -> [u64; PASSES] {
    core::array::from_fn(|pass| (0..height).flat_map(|y| (0..width).map(move |x| (x, y))).filter(|&(x, y)| traced_in_pass(pass, x, y)).count() as u64)
}

fn check<N: Number, P: Copy + Default + PartialEq + std::fmt::Debug>(
    name: &str,
    normal: impl Fn(&Scene<N, CAPACITY>, &mut FrameBuffer<'_, P>, &mut Statistics),
    progressive: impl Fn(&Scene<N, CAPACITY>, &mut FrameBuffer<'_, P>, &mut PassStatistics),
    mode: &str,
) {
    let mut description = load(name);
    let (width, height) = (description.viewport.width(), description.viewport.height());
    let count = usize::from(width) * usize::from(height);
    let expected_pixels = pass_pixels(width, height);
    let mut unoptimized: Option<Vec<P>> = None;
    for optimizations in Optimizations::combinations() {
        description.optimizations = optimizations;
        let scene = Box::new(Scene::<N, CAPACITY>::prepare(&description).unwrap());
        let mut reference = vec![P::default(); count];
        let mut statistics = Statistics::default();
        normal(&scene, &mut FrameBuffer::new(&mut reference, width, height).unwrap(), &mut statistics);
        let mut image = vec![P::default(); count];
        let mut passes = PassStatistics::default();
        progressive(&scene, &mut FrameBuffer::new(&mut image, width, height).unwrap(), &mut passes);
        let label = format!("{name} {} {mode} {optimizations:?}", N::NAME);
        if let Some(first) = image.iter().zip(&reference).position(|(a, b)| a != b) {
            panic!("{label}: the progressive image differs from the normal render at pixel {first} ({}, {})", first % usize::from(width), first / usize::from(width));
        }
        let unoptimized = unoptimized.get_or_insert_with(|| reference.clone());
        assert!(image == *unoptimized, "{label}: differs from the unoptimized render");
        let total = passes.total();
        assert_eq!(total.pixels, statistics.pixels, "{label}");
        assert_eq!(total.rays_traced, statistics.rays_traced, "{label}: rays");
        assert_eq!(total.rays_intersected, statistics.rays_intersected, "{label}: hits");
        for (pass, counts) in passes.passes.iter().enumerate() {
            assert_eq!(counts.pixels, expected_pixels[pass], "{label}: pass {pass}'s pixels");
            assert!(counts.rays_traced > 0 && counts.rays_traced <= counts.pixels, "{label}: pass {pass} traced {}", counts.rays_traced);
            if !optimizations.pixelbuffer {
                // Without Pixelbuffer every pixel of the pass gets a primary ray.
                assert_eq!(counts.rays_traced, counts.pixels, "{label}: pass {pass}");
            }
        }
    }
}

fn pga<N: Number>(name: &str) {
    check::<N, u8>(name, |scene, sink, statistics| render(scene, Pga, Whole, sink, statistics), |scene, sink, passes| render(scene, Pga, Progressive, sink, passes), "pga");
}

fn rgb<N: Number>(name: &str) {
    check::<N, [u8; 3]>(name, |scene, sink, statistics| render(scene, Rgb, Whole, sink, statistics), |scene, sink, passes| render(scene, Rgb, Progressive, sink, passes), "rgb");
}

#[test]
fn snooker_progressive_equals_normal_in_every_combination() {
    pga::<f64>("snooker.mts");
    pga::<f32>("snooker.mts");
    rgb::<f32>("snooker.mts");
}

#[test]
fn lattice_progressive_equals_normal_in_every_combination() {
    pga::<f64>("lattice.mts");
    pga::<f32>("lattice.mts");
    rgb::<f32>("lattice.mts");
}

#[test]
fn the_first_pass_traces_one_pixel_in_sixty_four() {
    let [first, second, third, last] = pass_pixels(264, 240);
    assert_eq!(first, 33 * 30);
    assert_eq!(first + second, 66 * 60);
    assert_eq!(first + second + third, 132 * 120);
    assert_eq!(first + second + third + last, 264 * 240);
}
