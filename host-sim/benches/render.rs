//! Whole-scene renders of both thesis scenes at small sizes, with no optimizations, the
//! thesis's six configurations' extremes and everything on, so regressions in the tracer or
//! the optimizations show. Run with `cargo bench -p microtrace-sim --bench render`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, Statistics, Whole, render};
use microtrace::model::Optimizations;
use microtrace_sim::scene_file;
use microtrace_sim::heap::HostPrepared;

fn renders(c: &mut Criterion) {
    let scenes = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/");
    let mut group = c.benchmark_group("render 132x120");
    group.sample_size(20);
    for name in ["snooker", "lattice"] {
        let mut description = scene_file::load(std::path::Path::new(&format!("{scenes}{name}.mts"))).expect("scene");
        description.fit_to_size(132, 120);
        for (label, optimizations) in [("none", Optimizations::NONE), ("all", Optimizations::ALL)] {
            description.optimizations = optimizations;
            let scene = Box::new(HostPrepared::<f64>::prepare(&*description).expect("prepare"));
            let (width, height) = (description.viewport.width(), description.viewport.height());
            let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
            group.bench_with_input(BenchmarkId::new(name, label), &scene, |b, scene| {
                b.iter(|| {
                    let mut statistics = Statistics::default();
                    render(&**scene, Pga, Whole, &mut FrameBuffer::new(&mut pixels, width, height).expect("sized"), &mut statistics);
                    statistics
                })
            });
        }
        // Preprocess alone (the acceleration structures).
        description.optimizations = Optimizations::ALL;
        group.bench_function(BenchmarkId::new(name, "prepare"), |b| {
            b.iter(|| Box::new(HostPrepared::<f64>::prepare(&*description).expect("prepare")))
        });
    }
    group.finish();
}

criterion_group!(benches, renders);
criterion_main!(benches);
