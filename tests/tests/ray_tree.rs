//! The ray tree and the lights of the thesis's chapter 5 (§5.2.2): hard cases in every number
//! type, what must not change, and the secondary rays' bounding spheres against brute force.

use microtrace::number::{F32Micro, Fixed, Fixed16, Number, SoftFloat};
use microtrace::model::Rgb888;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, Rgb, Statistics, Whole, render};
use microtrace::optimize::space_grid::SpaceGrid;
use microtrace::model::{Optimizations, SceneDescription};
use microtrace::scene::Scene;

const CAPACITY: usize = 80;

fn description(text: &str) -> SceneDescription<CAPACITY> {
    microtrace::parser::parse::<CAPACITY>(text.as_bytes()).unwrap_or_else(|error| panic!("{error}"))
}

fn scene_file(name: &str) -> SceneDescription<CAPACITY> {
    let path = format!("{}/../scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    description(&std::fs::read_to_string(&path).unwrap_or_else(|error| panic!("{path}: {error}")))
}

fn sized(mut scene: SceneDescription<CAPACITY>, width: u16, height: u16) -> SceneDescription<CAPACITY> {
    scene.viewport = microtrace::model::Viewport { x1: 0, x2: width - 1, y1: 0, y2: height - 1 };
    scene
}

/// How secondary rays find their objects.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Secondary {
    /// The uniform 3-D grid and the bounding spheres (the default).
    Grid,
    /// The bounding spheres of every object.
    Spheres,
    /// Every object's primitive.
    BruteForce,
}

/// Prepared, with the secondary rays' acceleration as asked.
fn prepare_with<N: Number>(scene: &SceneDescription<CAPACITY>, secondary: Secondary) -> Box<Scene<N, CAPACITY>> {
    let mut prepared = Box::new(Scene::<N, CAPACITY>::prepare(scene).unwrap_or_else(|error| panic!("{}: {error}", N::NAME)));
    if secondary != Secondary::Grid {
        prepared.space_grid = SpaceGrid::NONE;
    }
    if secondary == Secondary::BruteForce {
        prepared.spheres.clear();
    }
    prepared
}

fn prepare<N: Number>(scene: &SceneDescription<CAPACITY>, brute_force: bool) -> Box<Scene<N, CAPACITY>> {
    prepare_with(scene, if brute_force { Secondary::BruteForce } else { Secondary::Grid })
}

fn pga_with<N: Number>(scene: &SceneDescription<CAPACITY>, secondary: Secondary) -> (Vec<u8>, Statistics) {
    let prepared = prepare_with::<N>(scene, secondary);
    let (width, height) = (scene.viewport.width(), scene.viewport.height());
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let mut statistics = Statistics::default();
    render(&*prepared, Pga, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
    (pixels, statistics)
}

fn pga<N: Number>(scene: &SceneDescription<CAPACITY>, brute_force: bool) -> (Vec<u8>, Statistics) {
    let prepared = prepare::<N>(scene, brute_force);
    let (width, height) = (scene.viewport.width(), scene.viewport.height());
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let mut statistics = Statistics::default();
    render(&*prepared, Pga, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
    (pixels, statistics)
}

fn rgb<N: Number>(scene: &SceneDescription<CAPACITY>) -> (Vec<Rgb888>, Statistics) {
    let prepared = prepare::<N>(scene, false);
    let (width, height) = (scene.viewport.width(), scene.viewport.height());
    let mut pixels = vec![[0u8; 3]; usize::from(width) * usize::from(height)];
    let mut statistics = Statistics::default();
    render(&*prepared, Rgb, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
    (pixels, statistics)
}

fn same_share<P: PartialEq>(a: &[P], b: &[P]) -> f64 {
    a.iter().zip(b).filter(|(x, y)| x == y).count() as f64 / a.len() as f64
}

const HARD_CASES: [&str; 5] = ["ray-tree/facing-mirrors.mts", "ray-tree/glass-in-mirror.mts", "ray-tree/inside-glass.mts", "snooker-polished.mts", "ray-tree/mirror-balls.mts"];

/// Every hard case renders in every number type (no panic), and the accurate types agree with
/// `f64` on nearly every pixel. Measured at 64x48: f32, soft32 and fixed 100 % on all four (the
/// test asks 99.5 %); `fixed16` 52–90 % and `f32-micromath` 62–99 %, whose direction errors
/// (docs/hard-cases.md, deviation 30) grow down the tree: for those two the test asserts the
/// lowest measured share less a margin (50 %, 60 %), so that they render and do not get worse.
#[test]
fn the_hard_cases_render_in_every_number_type() {
    for name in HARD_CASES {
        let scene = sized(scene_file(name), 64, 48);
        let (reference, statistics) = pga::<f64>(&scene, false);
        assert!(statistics.secondary_rays_total() > 0, "{name}: no secondary rays");
        let shares = [
            ("f32", same_share(&reference, &pga::<f32>(&scene, false).0), 0.995),
            ("soft32", same_share(&reference, &pga::<SoftFloat>(&scene, false).0), 0.995),
            ("fixed", same_share(&reference, &pga::<Fixed>(&scene, false).0), 0.995),
            ("fixed16", same_share(&reference, &pga::<Fixed16>(&scene, false).0), 0.50),
            ("f32-micromath", same_share(&reference, &pga::<F32Micro>(&scene, false).0), 0.60),
        ];
        for (number, share, target) in shares {
            println!("{name} {number}: {:.2} % of pixels as f64", share * 100.0);
            assert!(share >= target, "{name} {number}: {:.2} % of pixels as f64, below {:.1} %", share * 100.0, target * 100.0);
        }
    }
}

/// Two facing mirrors at the format's full depth: every generation up to the seventh after the
/// primary is traced and none beyond (the explicit stack is full, not overflowed); a smaller
/// `depth` stops the tree there.
#[test]
fn facing_mirrors_fill_the_tree_to_its_depth() {
    let scene = sized(scene_file("ray-tree/facing-mirrors.mts"), 64, 48);
    assert_eq!(scene.depth, 8);
    for (number, statistics) in [("f64", pga::<f64>(&scene, false).1), ("f32", pga::<f32>(&scene, false).1), ("soft32", pga::<SoftFloat>(&scene, false).1)] {
        assert!(statistics.secondary_rays.iter().all(|count| *count > 0), "{number}: {:?}", statistics.secondary_rays);
    }
    let mut shallow = scene.clone();
    shallow.depth = 3;
    let statistics = pga::<f64>(&shallow, false).1;
    assert!(statistics.secondary_rays[0] > 0 && statistics.secondary_rays[1] > 0, "{:?}", statistics.secondary_rays);
    assert!(statistics.secondary_rays[2..].iter().all(|count| *count == 0), "{:?}", statistics.secondary_rays);
    let mut primary_only = scene.clone();
    primary_only.depth = 1;
    let (image, statistics) = pga::<f64>(&primary_only, false);
    assert_eq!(statistics.secondary_rays_total(), 0);
    // Depth 1 is the thesis's render: the same image as the scene without its mirrors' `reflect`.
    let mut matte = scene.clone();
    for object in matte.objects.iter_mut() {
        object.material.reflect = 0.0;
    }
    assert_eq!(image, pga::<f64>(&matte, false).0);
}

/// A clear object of index 1 changes no direction: a transparent ball (`transmit 1`, `ior 1`,
/// no local term, casting no shadow) in front of a red one leaves the RGB image as it is
/// without it, up to rounding (the secondary ray starts off the glass's surface).
#[test]
fn a_clear_ball_of_index_one_is_invisible() {
    let base = "viewport 0 79 0 59\nwindow -40 40 -30 30\nviewplane 0\nperspective 0 0 150\nlight point 60 80 120\nshadows on\n\
                cube\n  scale 200 200 2\n  translate -100 -100 -80\n  cmy 0.8 0.2 0.8\n  rnd 0\n\
                sphere\n  scale 14 14 14\n  translate 5 -3 -40\n  cmy 0 1 1\n  rnd 0\n";
    let glass = "sphere\n  scale 22 22 22\n  translate -6 4 10\n  ka 0\n  kd 0\n  ks 0\n  rnd 0\n  transmit 1\n  ior 1\n";
    let without = description(base);
    let with = description(&format!("{base}{glass}"));
    for number in ["f64", "f32"] {
        let ((plain, _), (seen_through, statistics)) = match number {
            "f64" => (rgb::<f64>(&without), rgb::<f64>(&with)),
            _ => (rgb::<f32>(&without), rgb::<f32>(&with)),
        };
        assert!(statistics.secondary_rays_total() > 500, "{number}: {:?}", statistics.secondary_rays);
        let largest = plain.iter().zip(&seen_through).flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| x.abs_diff(*y))).max().unwrap();
        let differing = plain.iter().zip(&seen_through).filter(|(a, b)| a != b).count();
        println!("{number}: {differing} pixels differ, by at most {largest}");
        assert!(largest <= 1 && differing * 200 <= plain.len(), "{number}: {differing} pixels differ, by at most {largest}");
    }
}

/// What a scene without chapter 5 renders must not change when it writes the defaults out, and
/// a second light of intensity 0 adds nothing to the image.
#[test]
fn defaults_written_out_and_a_dark_second_light_change_nothing() {
    let path = format!("{}/../scenes/snooker.mts", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).unwrap();
    let plain = sized(description(&text), 132, 120);
    let explicit = sized(description(&text.replace("light point 300 1400 900", "light point 300 1400 900 1\ndepth 8\nantialias off")), 132, 120);
    let dark = sized(description(&text.replace("light point 300 1400 900", "light point 300 1400 900\nlight point -500 900 900 0")), 132, 120);
    assert!(!explicit.uses_chapter_five() && dark.uses_chapter_five());
    let reference = pga::<f32>(&plain, false);
    assert_eq!(reference, pga::<f32>(&explicit, false));
    let (image, statistics) = pga::<f32>(&dark, false);
    assert_eq!(image, reference.0);
    assert!(statistics.shadow_rays > reference.1.shadow_rays, "the second light casts its own shadow rays");
}

/// A transparent blocker passes its share of the light (shadow rays are not refracted): the
/// floor in a ball's shadow is darkest under an opaque ball, brighter under a half-transparent
/// one, and as bright as the lit floor under a clear one.
#[test]
fn a_transparent_blocker_passes_its_share_of_the_light() {
    let floor_in_shadow = |transmit: f64| {
        let scene = description(&format!(
            "viewport 0 39 0 29\nwindow -40 40 -30 30\nviewplane 0\nparallel 0 0 -1\nlight direction 1 0 1\nshadows on\nambient 0.1\n\
             cube\n  scale 200 200 2\n  translate -100 -100 -80\n  rnd 0\n  ka 1\n  kd 0.8\n\
             sphere\n  scale 10 10 10\n  translate 0 0 -60\n  rnd 0\n  transmit {transmit}\n"
        ));
        // The shadow's centre lies 18 units toward −x (the ball is 18 above the floor, the light
        // at 45°): x = −24 is in it and outside the ball's silhouette (|x| ≤ 10).
        let (pixels, _) = rgb::<f64>(&scene);
        pixels[15 * 40 + 8].iter().map(|c| u32::from(*c)).sum::<u32>()
    };
    let lit = floor_in_shadow(1.0);
    let half = floor_in_shadow(0.5);
    let dark = floor_in_shadow(0.0);
    assert!(dark < half && half < lit, "opaque {dark}, half {half}, clear {lit}");
}

/// The secondary rays' acceleration skips tests and changes nothing: the uniform 3-D grid and
/// the bounding spheres alone give the same image and the same rays as brute force, with fewer
/// ray–object tests per secondary ray (the grid fewest on the scene of 65 mirrors).
#[test]
fn the_secondary_acceleration_changes_no_pixel_and_saves_tests() {
    for name in HARD_CASES {
        let scene = sized(scene_file(name), 64, 48);
        for number in ["f64", "f32", "fixed", "soft32"] {
            let run = |secondary| match number {
                "f64" => pga_with::<f64>(&scene, secondary),
                "f32" => pga_with::<f32>(&scene, secondary),
                "soft32" => pga_with::<SoftFloat>(&scene, secondary),
                _ => pga_with::<Fixed>(&scene, secondary),
            };
            let (grid, spheres, brute) = (run(Secondary::Grid), run(Secondary::Spheres), run(Secondary::BruteForce));
            assert_eq!(grid.0, brute.0, "{name} {number}: the grid's image");
            assert_eq!(spheres.0, brute.0, "{name} {number}: the spheres' image");
            assert_eq!(grid.1.secondary_rays, brute.1.secondary_rays, "{name} {number}");
            assert_eq!(spheres.1.secondary_rays, brute.1.secondary_rays, "{name} {number}");
            let per_ray = |s: &Statistics| s.secondary_tests as f64 / s.secondary_rays_total() as f64;
            println!(
                "{name} {number}: tests per secondary ray: grid {:.2}, bounding spheres {:.2}, brute force {:.2}",
                per_ray(&grid.1),
                per_ray(&spheres.1),
                per_ray(&brute.1)
            );
            assert!(spheres.1.secondary_tests < brute.1.secondary_tests, "{name} {number}");
            assert!(grid.1.secondary_tests <= spheres.1.secondary_tests, "{name} {number}");
            if name.contains("mirror-balls") {
                assert!(per_ray(&grid.1) < 0.5 * per_ray(&brute.1), "{name} {number}");
            }
        }
    }
}

/// The screen-space optimizations serve the primary rays of a scene with a ray tree as before:
/// all 16 combinations give the same image.
#[test]
fn every_optimization_combination_renders_the_same_tree() {
    let scene = sized(scene_file("snooker-polished.mts"), 96, 80);
    let mut none = scene.clone();
    none.optimizations = Optimizations::NONE;
    let reference = pga::<f32>(&none, false).0;
    for optimizations in Optimizations::combinations() {
        let mut each = scene.clone();
        each.optimizations = optimizations;
        assert_eq!(pga::<f32>(&each, false).0, reference, "{optimizations:?}");
    }
}
