//! Haines' SPD scenes read from NFF (issue 24): each renders with every optimization as with
//! none, pixel for pixel, in `f32` and (smaller) in every other number type, the scenes of more
//! than 128 objects with the shadow rays' hierarchy (`optimize::bvh`), transparent blockers
//! included.

use std::path::Path;

use microtrace::model::Optimizations;
use microtrace::number::{Fixed, Number, SoftFloat};
use microtrace::pixel::FrameBuffer;
use microtrace::render::{render, Rgb, Statistics, Whole};
use microtrace_sim::heap::{Growing, HostPrepared};
use microtrace_sim::scene_file::{self, HostScene};

fn rendered(description: &HostScene) -> (Vec<[u8; 3]>, Statistics) {
    rendered_in::<f32>(description)
}

fn rendered_in<N: Number>(description: &HostScene) -> (Vec<[u8; 3]>, Statistics) {
    let scene = HostPrepared::<N>::prepare(description).unwrap();
    let (width, height) = (description.viewport.width(), description.viewport.height());
    let mut pixels = vec![[0u8; 3]; usize::from(width) * usize::from(height)];
    let mut statistics = Statistics::default();
    render(&scene, Rgb, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
    (pixels, statistics)
}

/// All, none, and each optimization alone give the same picture.
fn same_with_every_optimization(name: &str, mut description: HostScene, size: u16) -> Statistics {
    description.fit_to_size(size, size);
    let (all, statistics) = rendered(&description);
    for optimizations in [Optimizations::NONE, Optimizations::from_list("extents").unwrap(), Optimizations::from_list("grid,sortlist").unwrap()] {
        description.optimizations = optimizations;
        let (other, _) = rendered(&description);
        let differing = all.iter().zip(&other).filter(|(a, b)| a != b).count();
        assert_eq!(differing, 0, "{name}: {differing} pixels differ with {optimizations:?}");
    }
    statistics
}

#[test]
fn the_spd_scenes_render_with_every_optimization_as_with_none() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/spd");
    // Teapot and gears: thousands of triangles cut into pieces for the hierarchy (gears' faces
    // the longest, some of them glass).
    for name in ["tree3.nff", "balls1.nff", "rings1.nff", "balls2.nff", "lattice1.nff", "jacks1.nff", "full/tree-s6.nff.gz", "full/rings-s2.nff.gz", "full/teapot.nff.gz", "full/gears.nff.gz"] {
        let description = scene_file::load(&folder.join(name)).unwrap();
        let many = description.objects.len() > microtrace::optimize::HIERARCHY_ABOVE;
        let prepared = HostPrepared::<f32>::prepare(&description).unwrap();
        assert_eq!(prepared.acceleration.hierarchy().is_some(), many, "{name}: a hierarchy exactly for more than {} objects", microtrace::optimize::HIERARCHY_ABOVE);
        // The adaptive screen grid: √(objects/2) cells across, from the thesis's 20 to 64.
        let side = (20..=64).rev().find(|side: &usize| 2 * side * side <= description.objects.len()).unwrap_or(20);
        assert_eq!(prepared.acceleration.grid_side(), Some(side as u16), "{name}");
        let statistics = same_with_every_optimization(name, *description, 24);
        assert!(statistics.shadow_rays > 0, "{name}");
    }
}

/// The hierarchy in every number type (fixed point's slab test saturates, never wraps): a
/// ladder's rung of spheres and cones, one of spheres and cylinders, and the teapot's triangles
/// cut into pieces, each with every optimization as with none. (Not Q16.16: these scenes are
/// beyond its range, and it draws the tree wrongly with every optimization and with none.)
#[test]
fn the_hierarchy_gives_the_same_pictures_in_every_number_type() {
    fn same<N: Number>(name: &str, description: &HostScene) {
        let many = description.objects.len() > 128;
        let prepared = HostPrepared::<N>::prepare(description).unwrap();
        assert_eq!(prepared.acceleration.hierarchy().is_some(), many, "{name} in {}", N::NAME);
        let (all, _) = rendered_in::<N>(description);
        let mut none = description.clone();
        none.optimizations = Optimizations::NONE;
        let (other, _) = rendered_in::<N>(&none);
        let differing = all.iter().zip(&other).filter(|(a, b)| a != b).count();
        assert_eq!(differing, 0, "{name} in {}: {differing} pixels differ", N::NAME);
    }
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/spd/full");
    for name in ["tree-s6.nff.gz", "rings-s2.nff.gz", "teapot.nff.gz"] {
        let mut description = *scene_file::load(&folder.join(name)).unwrap();
        description.fit_to_size(16, 16);
        same::<f64>(name, &description);
        same::<Fixed>(name, &description);
        same::<SoftFloat>(name, &description);
    }
}

/// 300 spheres, a third of them glass, over a floor, two lights: the shadow rays multiply the
/// glass blockers' transmission in object order through the hierarchy as without it.
#[test]
fn transparent_blockers_through_the_hierarchy_as_without_it() {
    let mut text = String::from("v from 0 -12 9 at 0 0 0 up 0 0 1 angle 50 hither 1 resolution 32 32\nb 0.2 0.3 0.5\nl 4 -6 20\nl -8 2 14 0.8 0.8 0.8\n");
    text.push_str("f 0.6 0.6 0.6 0.9 0 0 0 0\np 4\n-10 -10 0\n10 -10 0\n10 10 0\n-10 10 0\n");
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut random = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for index in 0..300 {
        let glass = index % 3 == 0;
        text.push_str(if glass { "f 0.8 0.9 1 0.2 0.3 30 0.7 1.4\n" } else { "f 0.9 0.4 0.2 0.7 0.3 20 0 0\n" });
        text.push_str(&format!("s {} {} {} {}\n", 16.0 * random() - 8.0, 16.0 * random() - 8.0, 0.5 + 4.0 * random(), 0.2 + 0.6 * random()));
    }
    let description: HostScene = microtrace::parser::nff::parse_into_list::<Growing<_>>(text.as_bytes()).unwrap();
    let prepared = HostPrepared::<f32>::prepare(&description).unwrap();
    assert!(prepared.acceleration.hierarchy().is_some());
    let statistics = same_with_every_optimization("glass spheres", description, 32);
    assert!(statistics.secondary_rays_total() > 0);
}

/// `bench --spd` end to end on two small rungs of the ladders at a small size: a row each, the
/// ladder's fit, and an unknown scene refused by name.
#[test]
fn bench_spd_reports_each_scene_and_the_ladder() {
    let run = |arguments: &[&str]| std::process::Command::new(env!("CARGO_BIN_EXE_microtrace")).args(arguments).current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("..")).output().unwrap();
    let output = run(&["bench", "--spd", "--spd-scenes", "tree-s6,tree-s7", "--spd-size", "16x16"]);
    let report = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    assert!(report.contains("| tree-s6 | 256 |") && report.contains("| tree-s7 | 512 |"), "{report}");
    assert!(report.contains("| tree | 256, 512 |"), "{report}");
    // The item buffer's rows: the hit cache's tests per primary ray, then the ideal buffer's,
    // never more.
    let item_buffer = report.split("## The item buffer").nth(1).unwrap_or_else(|| panic!("{report}"));
    let row = item_buffer.lines().find(|line| line.starts_with("| tree-s6 |")).unwrap_or_else(|| panic!("{report}"));
    let figures: Vec<f64> = row.split('|').filter_map(|cell| cell.trim().parse().ok()).collect();
    assert!(figures.len() == 2 && figures[1] <= figures[0] && figures[1] > 0.0, "{row}");
    let output = run(&["bench", "--spd", "--spd-scenes", "forest"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stderr).contains("--spd-scenes: no SPD scene `forest`"), "{}", String::from_utf8_lossy(&output.stderr));
}
