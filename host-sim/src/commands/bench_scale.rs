//! `microtrace bench --scale`: how the tracer's memory and time grow with the objects. For each
//! count, a generated field of spheres (`crate::sphere_field`, every optimization on, shadows
//! on) is parsed, prepared and rendered on one thread; the report gives the heap bytes each
//! step holds (counted by the program's allocator, `crate::allocation`: a machine-independent
//! figure), the times, and the tests per ray, as Markdown (docs/scale.md).

use std::fmt::Write as _;
use std::time::{Duration, Instant};

use anyhow::Context;
use microtrace::number::NumberKind;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{render, Pga, Statistics, Whole};
use microtrace::with_number_kind;

use crate::allocation;
use crate::files;
use crate::heap::{Growing, HostPrepared};
use crate::sphere_field::sphere_field;

use super::BenchArgs;

/// What one count measured.
struct Measured {
    count: usize,
    /// Heap bytes held by the parsed description, the prepared scene, and at most during the
    /// render over what the two held (per-render tables and the image).
    description_bytes: usize,
    prepared_bytes: usize,
    render_peak_bytes: usize,
    /// Heap bytes at most from parsing to the end of the render, the scene's text excluded.
    peak_bytes: usize,
    parse: Duration,
    prepare: Duration,
    trace: Duration,
    statistics: Statistics,
}

fn measure(count: usize, number: NumberKind, width: u16, height: u16) -> anyhow::Result<Measured> {
    let text = sphere_field(count, width, height);
    let base = allocation::current_bytes();
    allocation::reset_peak();
    let started = Instant::now();
    let description = microtrace::parser::parse_into_list::<Growing<_>>(text.as_bytes()).map_err(|error| anyhow::anyhow!("the generated scene does not parse: {error}"))?;
    let parse = started.elapsed();
    let described = allocation::current_bytes();
    with_number_kind!(number, N => {
        let started = Instant::now();
        let prepared = HostPrepared::<N>::prepare(&description).map_err(|error| anyhow::anyhow!("the generated scene does not prepare: {error}"))?;
        let prepare = started.elapsed();
        let ready = allocation::current_bytes();
        let before_render_peak = allocation::peak_bytes();
        allocation::reset_peak();
        let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
        let mut statistics = Statistics::default();
        let started = Instant::now();
        render(&prepared, Pga, Whole, &mut FrameBuffer::new(&mut pixels, width, height).context("the image's buffer")?, &mut statistics);
        let trace = started.elapsed();
        let render_peak = allocation::peak_bytes();
        Ok(Measured {
            count,
            description_bytes: described - base,
            prepared_bytes: ready - described,
            render_peak_bytes: render_peak - ready,
            peak_bytes: before_render_peak.max(render_peak) - base,
            parse,
            prepare,
            trace,
            statistics,
        })
    })
}

fn ratio(numerator: u64, denominator: u64) -> f64 {
    if denominator == 0 { 0.0 } else { numerator as f64 / denominator as f64 }
}

fn report(rows: &[Measured], number: NumberKind, width: u16, height: u16) -> String {
    let mut text = String::new();
    let _ = writeln!(text, "<!-- written by `microtrace bench --scale`; do not edit by hand -->");
    let _ = writeln!(text, "# How the tracer scales with the objects\n");
    let _ = writeln!(
        text,
        "A field of spheres on a floor (`host-sim/src/sphere_field.rs`), in perspective, one point light, \
         shadows on, every optimization on, `{}` at {width}x{height}, PGA mode, one thread. Bytes are the heap \
         the program's allocator counted (`host-sim/src/allocation.rs`): the same on any machine for the same \
         build. Times are this machine's, one run each. What grows faster than the objects, and \
         why: docs/plan-storage.md, \"Measured: 100,000 objects\".\n",
        number.name()
    );
    let _ = writeln!(text, "| spheres | description | prepared scene | render (over both) | peak | peak per sphere | parse | prepare | trace | primary tests per intersected pixel | shadow tests per shadow ray |");
    let _ = writeln!(text, "|---|---|---|---|---|---|---|---|---|---|---|");
    for row in rows {
        let s = &row.statistics;
        let _ = writeln!(
            text,
            "| {} | {} | {} | {} | {} | {:.0} B | {:.3} s | {:.3} s | {:.3} s | {:.3} | {:.3} |",
            row.count,
            bytes(row.description_bytes),
            bytes(row.prepared_bytes),
            bytes(row.render_peak_bytes),
            bytes(row.peak_bytes),
            row.peak_bytes as f64 / row.count.max(1) as f64,
            row.parse.as_secs_f64(),
            row.prepare.as_secs_f64(),
            row.trace.as_secs_f64(),
            ratio(s.ro_tests, s.rays_intersected),
            ratio(s.shadow_tests, s.shadow_rays),
        );
    }
    if rows.len() >= 2 {
        let _ = writeln!(text, "\nGrowth from one count to the next (the objects grew by the first column's factor):\n");
        let _ = writeln!(text, "| spheres | objects x | peak bytes x | prepare x | trace x | primary tests x | shadow tests x |");
        let _ = writeln!(text, "|---|---|---|---|---|---|---|");
        for pair in rows.windows(2) {
            let (a, b) = (&pair[0], &pair[1]);
            let _ = writeln!(
                text,
                "| {} → {} | {:.1} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} |",
                a.count,
                b.count,
                b.count as f64 / a.count.max(1) as f64,
                b.peak_bytes as f64 / a.peak_bytes.max(1) as f64,
                b.prepare.as_secs_f64() / a.prepare.as_secs_f64().max(1e-9),
                b.trace.as_secs_f64() / a.trace.as_secs_f64().max(1e-9),
                ratio(b.statistics.ro_tests, a.statistics.ro_tests),
                ratio(b.statistics.shadow_tests, a.statistics.shadow_tests),
            );
        }
    }
    text
}

fn bytes(count: usize) -> String {
    match count {
        0..1_000_000 => format!("{:.1} KB", count as f64 / 1e3),
        _ => format!("{:.1} MB", count as f64 / 1e6),
    }
}

pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    let number = NumberKind::from_name(&args.number).ok_or_else(|| anyhow::anyhow!("unknown number type `{}`", args.number))?;
    let (width, height) = args.size;
    if !allocation::is_counting() {
        anyhow::bail!("bench --scale counts the heap through the `microtrace` program's allocator, which this program does not install");
    }
    if args.counts.is_empty() || args.counts.contains(&0) {
        anyhow::bail!("--counts: give one or more sphere counts from 1 up, comma-separated");
    }
    let mut rows = Vec::new();
    for &count in &args.counts {
        eprintln!("bench --scale: {count} spheres ...");
        if let Some(directory) = &args.scenes_out {
            let path = directory.join(format!("spheres-{count}.mts"));
            let text = sphere_field(count, width, height);
            files::write_atomically(&path, |out| out.write_all(text.as_bytes())).with_context(|| format!("cannot write {}", path.display()))?;
        }
        rows.push(measure(count, number, width, height)?);
    }
    let text = report(&rows, number, width, height);
    print!("{text}");
    if let Some(path) = &args.out {
        files::write_atomically(path, |out| out.write_all(text.as_bytes())).with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
}
