//! `microtrace bench --spd`: Haines' Standard Procedural Databases at their standard sizes
//! (issue 24; `scenes/spd/full/`, docs/nff.md): each scene read from NFF, prepared and rendered
//! as the SPD's rules say (512x512, every light, reflection and refraction as the materials
//! give them), in RGB mode, on one thread and on all, with the tests a ray makes by kind, the
//! rays a second and the heap at its peak; then, along each size ladder (balls, rings, tree),
//! how the trace time grows with the objects: a least-squares line of the time against
//! ln(objects), and the slope of ln(time) against ln(objects).

use std::fmt::Write as _;
use std::num::NonZeroUsize;
use std::path::Path;
use std::time::{Duration, Instant};

use anyhow::Context;
use microtrace::number::NumberKind;
use microtrace::render::{nearest_hit_cached, Statistics};

use crate::allocation;
use crate::files;
use crate::heap::HostPrepared;
use crate::rendering::{render_scene_on_threads, Mode};
use crate::scene_file;

use super::BenchArgs;

/// The seven classic scenes, then the ladders' smaller sizes.
pub const SCENES: [&str; 16] =
    ["balls", "gears", "mount", "rings", "teapot", "tetra", "tree", "balls-s1", "balls-s2", "balls-s3", "rings-s1", "rings-s2", "rings-s3", "tree-s6", "tree-s7", "tree-s8"];

/// Each ladder, smallest first, its last rung the standard size.
const LADDERS: [[&str; 4]; 3] = [["balls-s1", "balls-s2", "balls-s3", "balls"], ["rings-s1", "rings-s2", "rings-s3", "rings"], ["tree-s6", "tree-s7", "tree-s8", "tree"]];

struct Measured {
    name: String,
    /// Primary tests per primary ray in `f32` with the hit cache (the previous pixel's object
    /// first) and with an ideal item buffer (the pixel's own nearest object first).
    item_buffer: (f64, f64),
    objects: usize,
    read: Duration,
    prepare: Duration,
    trace: Duration,
    trace_threaded: Duration,
    threads: usize,
    peak_bytes: usize,
    statistics: Statistics,
}

fn measure(folder: &Path, name: &str, number: NumberKind, size: (u16, u16), threads: NonZeroUsize) -> anyhow::Result<Measured> {
    let path = folder.join(format!("{name}.nff.gz"));
    let base = allocation::current_bytes();
    allocation::reset_peak();
    let started = Instant::now();
    let mut scene = scene_file::load(&path)?;
    let read = started.elapsed();
    scene.fit_to_size(size.0, size.1);
    let one = render_scene_on_threads(&scene, number, Mode::Rgb, None, NonZeroUsize::MIN).map_err(|error| scene_file::in_file(&path, error))?;
    let peak_bytes = allocation::peak_bytes().saturating_sub(base);
    let all = render_scene_on_threads(&scene, number, Mode::Rgb, None, threads).map_err(|error| scene_file::in_file(&path, error))?;
    if one.to_rgb() != all.to_rgb() {
        anyhow::bail!("{name}: the picture on {} threads differs from one thread's", threads.get());
    }
    Ok(Measured {
        item_buffer: item_buffer(&scene).map_err(|error| scene_file::in_file(&path, error.into()))?,
        name: name.to_owned(),
        objects: scene.objects.len(),
        read,
        prepare: one.preprocess,
        trace: one.trace,
        trace_threaded: all.trace,
        threads: threads.get(),
        peak_bytes,
        statistics: one.statistics,
    })
}

/// The item buffer the thesis proposes (§5.2.1, after Weghorst: the nearest object of each
/// pixel found by scan conversion, so its primary ray tests that object first) at its best,
/// against the hit cache: the primary rays traced in rows, once with the previous pixel's
/// object tried first, then with each pixel's own nearest object (from the first pass) tried
/// first. Primary tests per primary ray, in `f32`; the buffer's own cost is not counted.
fn item_buffer(scene: &scene_file::HostScene) -> Result<(f64, f64), microtrace::model::SceneError> {
    let prepared = HostPrepared::<f32>::prepare(scene)?;
    let (width, height) = (scene.viewport.width(), scene.viewport.height());
    let pixels = || (0..height).flat_map(move |row| (0..width).map(move |column| (column, row)));
    let (mut cached, mut ideal) = (Statistics::default(), Statistics::default());
    let mut nearest = Vec::with_capacity(usize::from(width) * usize::from(height));
    let mut last_hit = None;
    for (column, row) in pixels() {
        let pixel = prepared.camera.pixel(column, row);
        let hit = prepared.camera.primary_ray(pixel).and_then(|ray| {
            cached.rays_traced += 1;
            nearest_hit_cached(&prepared, &ray, pixel, &mut cached, &mut last_hit)
        });
        nearest.push(hit.map(|hit| hit.object as u32));
    }
    for ((column, row), own) in pixels().zip(nearest) {
        let pixel = prepared.camera.pixel(column, row);
        if let Some(ray) = prepared.camera.primary_ray(pixel) {
            ideal.rays_traced += 1;
            nearest_hit_cached(&prepared, &ray, pixel, &mut ideal, &mut own.clone());
        }
    }
    Ok((ratio(cached.ro_tests, cached.rays_traced), ratio(ideal.ro_tests, ideal.rays_traced)))
}

fn ratio(numerator: u64, denominator: u64) -> f64 {
    if denominator == 0 { 0.0 } else { numerator as f64 / denominator as f64 }
}

/// Every ray's tests over every ray: primary, shadow and secondary.
fn all_tests_per_ray(s: &Statistics) -> f64 {
    ratio(s.ro_tests + s.shadow_tests + s.secondary_tests, s.rays_traced + s.shadow_rays + s.secondary_rays_total())
}

/// The least-squares line y = a + b·x and its R².
fn fit(points: &[(f64, f64)]) -> (f64, f64, f64) {
    let n = points.len() as f64;
    let (mean_x, mean_y) = (points.iter().map(|p| p.0).sum::<f64>() / n, points.iter().map(|p| p.1).sum::<f64>() / n);
    let sxx: f64 = points.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
    let sxy: f64 = points.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
    let syy: f64 = points.iter().map(|p| (p.1 - mean_y).powi(2)).sum();
    let b = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let a = mean_y - b * mean_x;
    let r2 = if sxx > 0.0 && syy > 0.0 { sxy * sxy / (sxx * syy) } else { 1.0 };
    (a, b, r2)
}

fn report(rows: &[Measured], number: NumberKind, size: (u16, u16)) -> String {
    let mut text = String::new();
    let threads = rows.first().map_or(1, |row| row.threads);
    let _ = writeln!(text, "<!-- written by `microtrace bench --spd`; do not edit by hand -->");
    let _ = writeln!(text, "# Haines' SPD scenes at their standard sizes\n");
    let _ = writeln!(
        text,
        "Each scene of `scenes/spd/full/` read from NFF (docs/nff.md), at {}x{}, `{}`, RGB mode, every \
         optimization on, every light, reflection and refraction as the materials give them. Times are \
         this machine's, one run each; tests and rays are the same on any machine. *All tests per ray*: \
         primary, shadow and secondary tests over all those rays. Peak: the heap the program's allocator \
         counted from reading the scene to the end of the one-thread render.\n",
        size.0,
        size.1,
        number.name()
    );
    let _ = writeln!(
        text,
        "| scene | objects | read | prepare | trace, 1 thread | trace, {threads} threads | all tests per ray | primary tests per primary ray | shadow tests per shadow ray | secondary tests per secondary ray | rays | rays per second, 1 thread | peak |"
    );
    let _ = writeln!(text, "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for row in rows {
        let s = &row.statistics;
        let rays = s.rays_traced + s.shadow_rays + s.secondary_rays_total();
        let _ = writeln!(
            text,
            "| {} | {} | {:.3} s | {:.3} s | {:.3} s | {:.3} s | {:.2} | {:.2} | {:.2} | {:.2} | {} | {:.0} | {:.1} MB |",
            row.name,
            row.objects,
            row.read.as_secs_f64(),
            row.prepare.as_secs_f64(),
            row.trace.as_secs_f64(),
            row.trace_threaded.as_secs_f64(),
            all_tests_per_ray(s),
            ratio(s.ro_tests, s.rays_traced),
            ratio(s.shadow_tests, s.shadow_rays),
            ratio(s.secondary_tests, s.secondary_rays_total()),
            rays,
            rays as f64 / row.trace.as_secs_f64().max(1e-9),
            row.peak_bytes as f64 / 1e6,
        );
    }
    let _ = writeln!(
        text,
        "\n## The item buffer (§5.2.1)\n\nWeghorst's item buffer, which the thesis proposes for primary rays (each pixel's nearest \
         object found by scan conversion beforehand, so its ray tests that object first), at its best: \
         primary tests per primary ray in `f32`, the rays traced in rows with the previous pixel's object \
         tried first (the hit cache, as rendered), and with each pixel's own nearest object tried first \
         (taken from that first pass: no scan conversion could do better). The rest of the tests are the \
         candidates Extents, the grid and Sortlist cannot rule out before the hit. The buffer's own cost \
         is not counted.\n"
    );
    let _ = writeln!(text, "| scene | hit cache | ideal item buffer | saved |");
    let _ = writeln!(text, "|---|---:|---:|---:|");
    for row in rows {
        let (cached, ideal) = row.item_buffer;
        let _ = writeln!(text, "| {} | {cached:.2} | {ideal:.2} | {:.0} % |", row.name, 100.0 * (1.0 - ideal / cached.max(1e-9)));
    }
    // Each ladder by its standard scene's name, with the rungs measured.
    let ladders: Vec<(&str, Vec<&Measured>)> = LADDERS
        .iter()
        .map(|ladder| (ladder[3], ladder.iter().filter_map(|name| rows.iter().find(|row| row.name == *name)).collect::<Vec<_>>()))
        .filter(|(_, rungs)| rungs.len() >= 2)
        .collect();
    if !ladders.is_empty() {
        let _ = writeln!(
            text,
            "\n## Growth along the ladders\n\nThe one-thread trace time (preparation added) against the objects. *Per ln(objects)*: the \
             least-squares line time = a + b·ln(objects), its slope b and R² (a time linear in log(objects) \
             fits it well); *exponent*: the slope of ln(time) against ln(objects) (1 would be linear in the objects).\n"
        );
        let _ = writeln!(text, "| ladder | objects | times | per ln(objects): b | R² | exponent |");
        let _ = writeln!(text, "|---|---|---|---:|---:|---:|");
        for (name, rungs) in ladders {
            let time = |row: &Measured| (row.prepare + row.trace).as_secs_f64();
            let linear: Vec<(f64, f64)> = rungs.iter().map(|row| ((row.objects as f64).ln(), time(row))).collect();
            let logarithmic: Vec<(f64, f64)> = rungs.iter().map(|row| ((row.objects as f64).ln(), time(row).max(1e-9).ln())).collect();
            let (_, slope, r2) = fit(&linear);
            let (_, exponent, _) = fit(&logarithmic);
            let objects: Vec<String> = rungs.iter().map(|row| row.objects.to_string()).collect();
            let times: Vec<String> = rungs.iter().map(|row| format!("{:.3} s", time(row))).collect();
            let _ = writeln!(text, "| {name} | {} | {} | {slope:.4} s | {r2:.3} | {exponent:.2} |", objects.join(", "), times.join(", "));
        }
    }
    text
}

pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    let number = NumberKind::from_name(&args.number).ok_or_else(|| anyhow::anyhow!("unknown number type `{}`", args.number))?;
    if !allocation::is_counting() {
        anyhow::bail!("bench --spd counts the heap through the `microtrace` program's allocator, which this program does not install");
    }
    let folder = args.scenes.join("spd/full");
    let names: Vec<String> = if args.spd_scenes.is_empty() { SCENES.iter().map(|name| name.to_string()).collect() } else { args.spd_scenes.clone() };
    if let Some(unknown) = names.iter().find(|name| !SCENES.contains(&name.as_str())) {
        anyhow::bail!("--spd-scenes: no SPD scene `{unknown}` (the scenes: {})", SCENES.join(", "));
    }
    let threads = std::thread::available_parallelism().unwrap_or(NonZeroUsize::MIN);
    let size = args.spd_size;
    let mut rows = Vec::new();
    for (index, name) in names.iter().enumerate() {
        eprintln!("bench --spd: {name} ({} of {}) ...", index + 1, names.len());
        rows.push(measure(&folder, name, number, size, threads).with_context(|| format!("bench --spd: {name}"))?);
    }
    let text = report(&rows, number, size);
    print!("{text}");
    if let Some(path) = &args.out {
        files::write_atomically(path, |out| out.write_all(text.as_bytes())).with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::fit;

    #[test]
    fn the_fit_finds_a_line() {
        let (a, b, r2) = fit(&[(1.0, 3.0), (2.0, 5.0), (3.0, 7.0)]);
        assert!((a - 1.0).abs() < 1e-12 && (b - 2.0).abs() < 1e-12 && (r2 - 1.0).abs() < 1e-12);
    }
}
