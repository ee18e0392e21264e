//! Both thesis scenes render, and single precision agrees with double precision on at least
//! 99.9% of pixels at the thesis's own sizes.

use microtrace::number::Number;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{render_pga, Statistics};
use microtrace::scene::{Scene, SceneDescription};

const CAPACITY: usize = 64;

fn load(name: &str) -> SceneDescription<CAPACITY> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/").to_owned() + name;
    let text = std::fs::read(&path).unwrap();
    microtrace::parser::parse::<CAPACITY>(&text).unwrap_or_else(|error| panic!("{path}: {error}"))
}

fn render<N: Number>(description: &SceneDescription<CAPACITY>) -> (Vec<u8>, Statistics) {
    let scene = Scene::<N, CAPACITY>::prepare(description).unwrap();
    let viewport = description.viewport;
    let mut pixels = vec![0u8; viewport.pixel_count() as usize];
    let mut frame = FrameBuffer::new(&mut pixels, viewport.width(), viewport.height()).unwrap();
    let mut statistics = Statistics::default();
    render_pga(&scene, &mut frame, &mut statistics);
    (pixels, statistics)
}

fn agreement(name: &str, objects: usize, pixel_count: u64) {
    let description = load(name);
    assert_eq!(description.objects.len(), objects);
    let (reference, statistics) = render::<f64>(&description);
    assert_eq!(statistics.pixels, pixel_count);
    // The scene is really there: a good share of pixels are objects, several colour groups show.
    let background = description.background;
    let object_pixels = reference.iter().filter(|&&index| index != background).count() as f64 / reference.len() as f64;
    assert!(object_pixels > 0.05, "{name}: only {:.1}% of pixels show objects", object_pixels * 100.0);
    let groups: std::collections::BTreeSet<u8> = reference.iter().map(|index| index / 16).collect();
    assert!(groups.len() >= 3, "{name}: colour groups {groups:?}");

    let (single, _) = render::<f32>(&description);
    let same = reference.iter().zip(&single).filter(|(a, b)| a == b).count();
    let fraction = same as f64 / reference.len() as f64;
    println!("{name}: f32 agrees with f64 on {:.4}% of {} pixels", fraction * 100.0, reference.len());
    assert!(fraction >= 0.999, "{name}: f32 agrees with f64 on only {:.4}% of pixels", fraction * 100.0);
}

#[test]
fn snooker_f32_agrees_with_f64() {
    agreement("snooker.mts", 21, 528 * 480);
}

#[test]
fn lattice_f32_agrees_with_f64() {
    agreement("lattice.mts", 54, 466 * 480);
}
