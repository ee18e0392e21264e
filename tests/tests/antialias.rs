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

/// The mean absolute error (per channel, over the image) of `image` against `reference`, a
/// render `factor` times finer in each direction averaged over each pixel's `factor`² samples.
fn error_against_supersampled(image: &[Rgb888], width: u16, reference: &[Rgb888], factor: usize) -> f64 {
    let (width, fine_width) = (usize::from(width), usize::from(width) * factor);
    let mut total = 0.0;
    for (index, pixel) in image.iter().enumerate() {
        let (column, row) = (index % width, index / width);
        for channel in 0..3 {
            let mut sum = 0.0;
            for dy in 0..factor {
                for dx in 0..factor {
                    sum += f64::from(reference[(row * factor + dy) * fine_width + column * factor + dx][channel]);
                }
            }
            total += (f64::from(pixel[channel]) - sum / (factor * factor) as f64).abs();
        }
    }
    total / (image.len() * 3) as f64
}

/// The scene at `factor` times the resolution, each pixel's samples spread evenly over that
/// pixel's area: the window widened by (factor − 1)/2 of a fine sample's spacing on each side
/// (pixels sit on the window's edges, digest §3.1, so a fine render of the same window would put
/// its samples off the coarse pixels' centres, by up to 3/8 of a pixel at the edges for 4x).
fn supersampled(scene: &SceneDescription<CAPACITY>, factor: u16) -> SceneDescription<CAPACITY> {
    let (width, height) = (scene.viewport.width(), scene.viewport.height());
    let mut fine = scene.clone();
    fine.antialias = None;
    fine.viewport = microtrace::model::Viewport { x1: 0, x2: width * factor - 1, y1: 0, y2: height * factor - 1 };
    let spread = f64::from(factor - 1) / 2.0 / f64::from(factor);
    let (spacing_x, spacing_y) = ((scene.window.x2 - scene.window.x1) / f64::from(width - 1), (scene.window.y2 - scene.window.y1) / f64::from(height - 1));
    fine.window.x1 -= spread * spacing_x;
    fine.window.x2 += spread * spacing_x;
    fine.window.y1 -= spread * spacing_y;
    fine.window.y2 += spread * spacing_y;
    fine
}

/// Chapter 5's goal for antialiasing: on snooker in RGB mode at 128x64 with `antialias 0.05 3`,
/// at most half the plain render's mean absolute error against a 4x4-supersampled reference
/// (each pixel's area sampled 16 times, box-filtered; docs/antialiasing.md). The balls'
/// roughness (`rnd`) is PGA mode's only, so RGB mode has none to turn off.
#[test]
fn antialiasing_halves_the_error_against_a_supersampled_reference() {
    let path = format!("{}/../scenes/snooker.mts", env!("CARGO_MANIFEST_DIR"));
    let mut plain = description(&std::fs::read_to_string(path).unwrap());
    plain.fit_to_size(128, 64);
    let mut antialiased = plain.clone();
    antialiased.antialias = Some(microtrace::model::Antialias { threshold: 0.05, levels: 3 });
    let (reference, _) = rgb(&supersampled(&plain, 4));
    let (plain_image, _) = rgb(&plain);
    let (antialiased_image, statistics) = rgb(&antialiased);
    let plain_error = error_against_supersampled(&plain_image, 128, &reference, 4);
    let antialiased_error = error_against_supersampled(&antialiased_image, 128, &reference, 4);
    let ratio = antialiased_error / plain_error;
    println!(
        "plain {plain_error:.3}, antialiased {antialiased_error:.3} ({:.2} rays a pixel): {ratio:.3} of the plain error",
        statistics.rays_traced as f64 / statistics.pixels as f64
    );
    assert!(ratio <= 0.5, "the antialiased error {antialiased_error:.3} is {ratio:.3} of the plain {plain_error:.3}");
    // The reference must sample each pixel's own area: the same window at 512x256 puts its
    // samples up to 3/8 of a pixel off, and the error against it is mostly that shift.
    let mut shifted = plain.clone();
    shifted.fit_to_size(512, 256);
    let (shifted_reference, _) = rgb(&shifted);
    let shifted_plain = error_against_supersampled(&plain_image, 128, &shifted_reference, 4);
    let shifted_antialiased = error_against_supersampled(&antialiased_image, 128, &shifted_reference, 4);
    println!("against the shifted reference: plain {shifted_plain:.3}, antialiased {shifted_antialiased:.3}: {:.3}", shifted_antialiased / shifted_plain);
    assert!(shifted_antialiased > 2.0 * antialiased_error, "the shifted reference's error {shifted_antialiased:.3} against the aligned {antialiased_error:.3}");
}
