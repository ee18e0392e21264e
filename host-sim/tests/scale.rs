//! Scenes far beyond a microcontroller's: the host's tables are sized by the scene (issue 22),
//! so ten thousand objects render with every optimization, in the same image as with none,
//! preparing them grows like n·log n, and more objects than a `u16` numbers keep every one in
//! the test order.

use microtrace::pixel::FrameBuffer;
use microtrace::render::{render, Pga, Statistics, Whole};
use microtrace::model::Optimizations;
use microtrace::parser::parse_into_list;
use microtrace_sim::heap::{Growing, HostPrepared};
use microtrace_sim::scene_file::HostScene;
use microtrace_sim::sphere_field::sphere_field;

fn field(count: usize, width: u16, height: u16) -> HostScene {
    parse_into_list::<Growing<_>>(sphere_field(count, width, height).as_bytes()).unwrap()
}

fn rendered(description: &HostScene) -> (Vec<u8>, Statistics) {
    let scene = HostPrepared::<f32>::prepare(description).unwrap();
    let (width, height) = (description.viewport.width(), description.viewport.height());
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let mut statistics = Statistics::default();
    render(&scene, Pga, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
    (pixels, statistics)
}

#[test]
fn ten_thousand_spheres_render_with_every_optimization_as_with_none() {
    let mut description = field(10_000, 48, 36);
    let scene = HostPrepared::<f32>::prepare(&description).unwrap();
    // 24 entries an object would not fit a `u16` pool (the grid switched off above about
    // 2,700 objects before the index was the Config's).
    assert!(scene.acceleration.grid_active(), "the grid is on");
    assert!(scene.acceleration.grid_entries() > usize::from(u16::MAX) || scene.acceleration.grid_capacity() > usize::from(u16::MAX));
    let (all, statistics) = rendered(&description);
    // The field is a trapezoid in perspective, its far spheres smaller than a pixel: a tenth of
    // the picture at least shows spheres.
    let spheres = all.iter().filter(|&&index| index != 0).count();
    assert!(spheres > all.len() / 10, "only {spheres} of {} pixels show a sphere", all.len());
    // The optimizations do their work: a few tests a ray, not thousands.
    let per_ray = statistics.ro_tests as f64 / statistics.rays_traced as f64;
    assert!(per_ray < 20.0, "{per_ray:.1} primary tests a ray");
    description.optimizations = Optimizations::NONE;
    let (none, unoptimized) = rendered(&description);
    assert!(unoptimized.ro_tests >= 10_000 * unoptimized.rays_traced, "without the optimizations every ray tests every sphere");
    assert!(all == none, "the optimizations change no pixel");
}

/// Preparing grows like n·log n, not like the pairs of objects (issue 24: the hierarchy's
/// build, the grid, the depth order): 20,000 spheres against 2,000, each the fastest of five
/// preparations, side by side in one run. n·log n makes the ratio about 13, n² about 100; the
/// bound leaves room for a loaded machine.
#[test]
fn preparation_grows_no_faster_than_n_log_n() {
    let fastest = |count: usize| {
        let description = field(count, 64, 48);
        let scene = HostPrepared::<f32>::prepare(&description).unwrap();
        assert!(scene.acceleration.hierarchy().is_some(), "{count} spheres have the hierarchy");
        (0..5)
            .map(|_| {
                let started = std::time::Instant::now();
                let scene = HostPrepared::<f32>::prepare(&description).unwrap();
                let elapsed = started.elapsed();
                drop(scene);
                elapsed
            })
            .min()
            .unwrap_or_default()
    };
    let (small, large) = (fastest(2_000), fastest(20_000));
    let ratio = large.as_secs_f64() / small.as_secs_f64().max(1e-6);
    println!("preparing 20,000 spheres: {large:?}; 2,000: {small:?}; ratio {ratio:.1}");
    assert!(ratio < 40.0, "20,000 spheres took {ratio:.1} times as long to prepare as 2,000 ({large:?} against {small:?})");
}

#[test]
fn more_objects_than_a_u16_numbers_are_all_in_the_test_order() {
    let description = field(70_000, 8, 6);
    let scene = HostPrepared::<f32>::prepare(&description).unwrap();
    let mut order: Vec<usize> = scene.acceleration.order().iter().map(|&object| object as usize).collect();
    assert_eq!(order.len(), 70_000);
    order.sort_unstable();
    assert!(order.iter().enumerate().all(|(place, &object)| place == object), "each object once");
}
