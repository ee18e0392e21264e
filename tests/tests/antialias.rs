//! Adaptive antialiasing (thesis §2.3.3, fig 2.9; `core/src/render/antialias.rs`): what it
//! traces, what it averages, and that the optimizations and the bands of a threaded render leave
//! the image as it is.

use microtrace::number::{Fixed, Number, SoftFloat};
use microtrace::model::Rgb888;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, Rgb, Rows, Statistics, Whole, render};
use microtrace::model::{Optimizations, SceneDescription};
use microtrace::scene::Scene;

const CAPACITY: usize = 64;

fn description(text: &str) -> SceneDescription<CAPACITY> {
    microtrace::parser::parse::<CAPACITY>(text.as_bytes()).unwrap_or_else(|error| panic!("{error}"))
}

fn lattice(width: u16, height: u16) -> SceneDescription<CAPACITY> {
    let path = format!("{}/../scenes/lattice-antialiased.mts", env!("CARGO_MANIFEST_DIR"));
    let mut scene = description(&std::fs::read_to_string(path).unwrap());
    scene.fit_to_size(width, height);
    scene
}

fn pga<N: Number>(scene: &SceneDescription<CAPACITY>) -> (Vec<u8>, Statistics) {
    let prepared = Box::new(Scene::<N, CAPACITY>::prepare(scene).unwrap_or_else(|error| panic!("{error}")));
    let (width, height) = (scene.viewport.width(), scene.viewport.height());
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let mut statistics = Statistics::default();
    render(&*prepared, Pga, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
    (pixels, statistics)
}

fn rgb(scene: &SceneDescription<CAPACITY>) -> (Vec<Rgb888>, Statistics) {
    let prepared = Box::new(Scene::<f64, CAPACITY>::prepare(scene).unwrap());
    let (width, height) = (scene.viewport.width(), scene.viewport.height());
    let mut pixels = vec![[0u8; 3]; usize::from(width) * usize::from(height)];
    let mut statistics = Statistics::default();
    render(&*prepared, Rgb, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
    (pixels, statistics)
}

/// The four optimizations serve the corner and sub-corner rays: all 16 combinations give the
/// antialiased lattice's image at 128x64.
#[test]
fn every_optimization_combination_gives_the_same_antialiased_image() {
    let scene = lattice(128, 64);
    let mut none = scene.clone();
    none.optimizations = Optimizations::NONE;
    let (reference, plain) = pga::<f32>(&none);
    println!("opt none: {:.2} rays per pixel", plain.rays_traced as f64 / plain.pixels as f64);
    for optimizations in Optimizations::combinations() {
        let mut each = scene.clone();
        each.optimizations = optimizations;
        let (image, statistics) = pga::<f32>(&each);
        assert_eq!(image, reference, "{optimizations:?}");
        assert_eq!(statistics.pixels, 128 * 64);
        assert!(statistics.rays_traced <= plain.rays_traced, "{optimizations:?}");
    }
}

/// Without a split every pixel is the mean of its four corners, and the corners are shared:
/// (W+1)·(H+1) rays for a W x H image (no optimization skipping any).
#[test]
fn corners_are_shared_and_a_flat_image_is_never_split() {
    let flat = "viewport 0 19 0 9\nbackground 100\nantialias 0 4\noptimize none\n";
    let (image, statistics) = rgb(&description(flat));
    assert_eq!(statistics.rays_traced, 21 * 11);
    assert_eq!(statistics.pixels, 200);
    let background = Scene::<f64, CAPACITY>::prepare(&description(flat)).unwrap().background_rgb();
    assert!(image.iter().all(|pixel| *pixel == background));
    // Threshold 1 never splits, whatever the corners.
    let mut never = lattice(40, 20);
    never.antialias.as_mut().unwrap().threshold = 1.0;
    never.optimizations = Optimizations::NONE;
    assert_eq!(rgb(&never).1.rays_traced, 41 * 21);
}

/// A pixel split by an edge is a mix: a white cube's vertical edge through the middle of a
/// column of pixels gives them a grey between the cube's and the background's, and more levels
/// trace more rays but never more than (2^L + 1)² per pixel.
#[test]
fn an_edge_through_a_pixel_mixes_its_colours() {
    let scene = |levels: u8| {
        description(&format!(
            "viewport 0 9 0 9\nwindow 0 9 0 9\nparallel 0 0 -1\nbackground 0\nambient 1\nantialias 0.05 {levels}\noptimize none\n\
             cube\n  scale 9.5 20 1\n  translate -5 -5 0\n  ka 1\n  kd 0\n  ks 0\n  rnd 0\n  cmy 0 0 0\n"
        ))
    };
    for levels in 1..=4u8 {
        let (image, statistics) = rgb(&scene(levels));
        // Pixel centres at x = 0..9, the cube covers x ≤ 4.5: pixels 0..=4 (up to 4.5) are
        // white, pixel 5 (4.5..5.5) has the edge at its left side, 6..=9 are black.
        let row = &image[50..60];
        assert!(row[..5].iter().all(|pixel| *pixel == [255, 255, 255]), "levels {levels}: {row:?}");
        assert_eq!(row[9], [0, 0, 0], "levels {levels}: {row:?}");
        let per_pixel = statistics.rays_traced as f64 / statistics.pixels as f64;
        let bound = f64::from((1u32 << levels) + 1).powi(2);
        assert!(per_pixel <= bound, "levels {levels}: {per_pixel} rays per pixel");
        assert!(row.windows(2).all(|pair| pair[0][0] >= pair[1][0]), "levels {levels}: {row:?}");
    }
    // A cube edge at x = 4.2: pixel 4 (3.5..4.5) is 70 % white; four levels (squares of 1/16)
    // find 11.5 of 16 (72 %, 183).
    let partial = description(
        "viewport 0 9 0 9\nwindow 0 9 0 9\nparallel 0 0 -1\nbackground 0\nambient 1\nantialias 0.05 4\noptimize none\n\
         cube\n  scale 9.2 20 1\n  translate -5 -5 0\n  ka 1\n  kd 0\n  ks 0\n  rnd 0\n  cmy 0 0 0\n",
    );
    let (image, _) = rgb(&partial);
    let grey = image[54][0];
    assert!((175..=190).contains(&grey), "pixel 4: {grey} (70 % of 255 is 179)");
}

/// The bands of a threaded render trace their own top corners again: the image is the whole
/// render's.
#[test]
fn bands_give_the_whole_image() {
    let scene = lattice(96, 48);
    let (whole, _) = pga::<f32>(&scene);
    let prepared = Box::new(Scene::<f32, CAPACITY>::prepare(&scene).unwrap());
    let mut pixels = vec![0u8; 96 * 48];
    let mut frame = FrameBuffer::new(&mut pixels, 96, 48).unwrap();
    for band in [0..17, 17..18, 18..48] {
        render(&*prepared, Pga, Rows(band), &mut frame, &mut Statistics::default());
    }
    assert_eq!(pixels, whole);
}

/// Every accurate number type antialiases as `f64` does, nearly pixel for pixel.
#[test]
fn the_number_types_agree() {
    let scene = lattice(128, 64);
    let (reference, _) = pga::<f64>(&scene);
    for (name, image) in [("f32", pga::<f32>(&scene).0), ("soft32", pga::<SoftFloat>(&scene).0), ("fixed", pga::<Fixed>(&scene).0)] {
        let same = image.iter().zip(&reference).filter(|(a, b)| a == b).count() as f64 / reference.len() as f64;
        println!("{name}: {:.2} % as f64", same * 100.0);
        assert!(same >= 0.99, "{name}: {:.2} % as f64", same * 100.0);
    }
}
