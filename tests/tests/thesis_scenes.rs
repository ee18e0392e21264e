//! Both thesis scenes render, and single precision agrees with double precision on at least
//! 99.9% of pixels at the thesis's own sizes. The targets for the other number types, at
//! 528x480 and at the OLED's 128x64: `f32` ≥ 99.95% of pixels identical to `f64`; Q32.32
//! `fixed` ≥ 99.5% identical, no pixel more than one shade step away and no speckles; `soft32`
//! (software floating point) is held to `f32`'s target.

use microtrace::number::{Fixed, Number, SoftFloat};
use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, Statistics, Whole};
use microtrace::model::SceneDescription;
use microtrace::scene::Scene;

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
    microtrace::render::render(&scene, Pga, Whole, &mut frame, &mut statistics);
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

/// How an image in another number type compares with the `f64` image of the same scene.
struct Comparison {
    identical: f64,
    /// Pixels whose shade (index & 15) is more than one step from `f64`'s, or whose colour
    /// group differs.
    beyond_one_shade: usize,
    /// Pixels that differ from `f64` and from all eight neighbours in their own image.
    speckles: usize,
}

fn compare(reference: &[u8], image: &[u8], width: usize, height: usize) -> Comparison {
    let same = reference.iter().zip(image).filter(|(a, b)| a == b).count();
    let beyond_one_shade = reference
        .iter()
        .zip(image)
        .filter(|(a, b)| *a / 16 != *b / 16 || (i32::from(*a & 15) - i32::from(*b & 15)).abs() > 1)
        .count();
    let mut speckles = 0;
    for row in 0..height {
        for column in 0..width {
            let index = row * width + column;
            if image[index] == reference[index] {
                continue;
            }
            let mut neighbours = (-1i64..=1)
                .flat_map(|dy| (-1i64..=1).map(move |dx| (dx, dy)))
                .filter(|&(dx, dy)| (dx, dy) != (0, 0))
                .filter_map(|(dx, dy)| {
                    let (x, y) = (column as i64 + dx, row as i64 + dy);
                    (x >= 0 && y >= 0 && (x as usize) < width && (y as usize) < height).then(|| image[y as usize * width + x as usize])
                });
            if neighbours.all(|neighbour| neighbour != image[index]) {
                speckles += 1;
            }
        }
    }
    Comparison { identical: same as f64 / reference.len() as f64, beyond_one_shade, speckles }
}

fn targets_at_size(name: &str, width: u16, height: u16) {
    let mut description = load(name);
    description.fit_to_size(width, height);
    let (reference, _) = render::<f64>(&description);
    let (size_w, size_h) = (usize::from(width), usize::from(height));

    let (single, _) = render::<f32>(&description);
    let single = compare(&reference, &single, size_w, size_h);
    let (fixed, _) = render::<Fixed>(&description);
    let fixed = compare(&reference, &fixed, size_w, size_h);
    let (soft, _) = render::<SoftFloat>(&description);
    let soft = compare(&reference, &soft, size_w, size_h);
    println!(
        "{name} {width}x{height}: f32 {:.4}% identical; fixed {:.4}% identical, {} beyond one shade, {} speckles; soft32 {:.4}% identical",
        single.identical * 100.0,
        fixed.identical * 100.0,
        fixed.beyond_one_shade,
        fixed.speckles,
        soft.identical * 100.0
    );
    assert!(single.identical >= 0.9995, "{name} {width}x{height}: f32 {:.4}% identical", single.identical * 100.0);
    // soft32 is held to f32's target.
    assert!(soft.identical >= 0.9995, "{name} {width}x{height}: soft32 {:.4}% identical", soft.identical * 100.0);
    assert!(fixed.identical >= 0.995, "{name} {width}x{height}: fixed {:.4}% identical", fixed.identical * 100.0);
    assert_eq!(fixed.beyond_one_shade, 0, "{name} {width}x{height}: fixed pixels more than one shade from f64");
    assert_eq!(fixed.speckles, 0, "{name} {width}x{height}: fixed speckles");
}

#[test]
fn snooker_targets_for_f32_and_fixed() {
    targets_at_size("snooker.mts", 528, 480);
    targets_at_size("snooker.mts", 128, 64);
}

#[test]
fn lattice_targets_for_f32_and_fixed() {
    targets_at_size("lattice.mts", 528, 480);
    targets_at_size("lattice.mts", 128, 64);
}

#[test]
fn speckle_detector_finds_an_isolated_pixel() {
    // The detector itself: one changed pixel in a flat image is a speckle, a changed 2x1 run is not.
    let reference = vec![5u8; 16];
    let mut image = reference.clone();
    image[5] = 6;
    let single = compare(&reference, &image, 4, 4);
    assert_eq!((single.speckles, single.beyond_one_shade), (1, 0));
    image[6] = 6;
    assert_eq!(compare(&reference, &image, 4, 4).speckles, 0);
    image[6] = 8;
    assert_eq!(compare(&reference, &image, 4, 4).beyond_one_shade, 1);
}

/// The CSG scenes (issue 23) are held to the same targets, at their own size and at 128x64.
#[test]
fn csg_scene_targets_for_f32_fixed_and_soft32() {
    for name in ["csg/die.mts", "csg/lens.mts", "csg/cup.mts", "csg/nut.mts"] {
        targets_at_size(name, 256, 192);
        targets_at_size(name, 128, 64);
    }
}
