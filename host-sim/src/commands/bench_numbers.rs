//! `microtrace bench --numbers`: speed against error for every number type.
//!
//! Renders the thesis scenes at their own size and at 128x64 and every scene in `scenes/hard/`
//! with every number type (PGA mode, the scenes' own settings), compares each image with the
//! f64 render of the same scene, times the types side by side in one process, reads the
//! Cortex-M instruction counts from the firmware report when there is one, and writes a
//! Markdown report and a PNG plot.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Duration;

use anyhow::Context;
use microtrace::model::{SceneError, SceneErrorKind};

use crate::files;
use crate::image_difference::{percent, ImageDifference};
use microtrace::number::NumberKind;
use crate::rendering::{render_scene, Mode, Pixels};
use crate::scene_file::{self, HostScene};

#[path = "bench_numbers_clock.rs"]
mod clock;
#[path = "bench_numbers_firmware.rs"]
mod firmware;
#[path = "bench_numbers_plot.rs"]
mod plot;

use firmware::{Build, FirmwareFigures, CORTEX_M0_BOARD, CORTEX_M33_BOARD, CORTEX_M3_BOARD, CORTEX_M4F_BOARD};
use plot::{BoardPanel, BoardPoint, PlotPoint};

pub const DEFAULT_REPORT: &str = "docs/numbers.md";
pub const DEFAULT_PLOT: &str = "docs/images/numbers.png";
pub const DEFAULT_FIRMWARE_REPORT: &str = "docs/firmware-report.json";

const THESIS_SCENES: [&str; 2] = ["snooker.mts", "lattice.mts"];
const SMALL_SIZE: (u16, u16) = (128, 64);

/// Timing: every scene is rendered round-robin (all types, then all types again, ...), at least
/// `MIN_ROUNDS` and at most `MAX_ROUNDS` times, as many as fit `ROUND_BUDGET` judging by the first
/// round; each type's time is the median of its rounds.
const MIN_ROUNDS: usize = 7;
const MAX_ROUNDS: usize = 41;
const ROUND_BUDGET: Duration = Duration::from_secs(4);

/// The targets.
const FIXED_IDENTICAL_PERCENT: f64 = 99.5;
const FIXED_LARGEST_SHADE_STEP: u8 = 1;
const F32_IDENTICAL_PERCENT: f64 = 99.95;
const CORTEX_M3_FIXED_SPEEDUP: f64 = 3.0;

/// Everything after this heading in an existing report is hand-written and kept as it is.
const HAND_WRITTEN_HEADING: &str = "## Notes (hand-written, kept by `bench --numbers`)";

/// The scene groups, one point per number type each in the plot.
const GROUP_FULL: &str = "thesis scenes, own size";
const GROUP_SMALL: &str = "thesis scenes, 128x64";
const GROUP_HARD: &str = "hard cases (scenes/hard)";
const GROUPS: [&str; 3] = [GROUP_FULL, GROUP_SMALL, GROUP_HARD];

/// One scene at one size.
struct Case {
    group: &'static str,
    /// The file stem, as the firmware report names scenes.
    stem: String,
    scene: Box<HostScene>,
}

impl Case {
    fn label(&self) -> String {
        format!("{} {}x{}", self.stem, self.scene.viewport.width(), self.scene.viewport.height())
    }
}

/// What one number type made of one case.
enum Outcome {
    Rendered { indices: Vec<u8>, times: Vec<Duration> },
    /// The scene is beyond the type's range (scene preparation says so).
    OutOfRange(String),
    Failed(String),
}

struct Measured {
    number: NumberKind,
    outcome: Outcome,
    difference: Option<ImageDifference>,
    median: Option<Duration>,
}

/// A hard-case file that could not be read: reported, not rendered.
struct UnreadableScene {
    stem: String,
    error: String,
}

/// Where the Cortex-M figures come from, and why they could not be used if so.
struct FirmwareSource {
    figures: FirmwareFigures,
    path: PathBuf,
    problem: Option<String>,
}

/// f32's instructions per pixel on Cortex-M3 over another type's.
#[derive(Clone, Copy)]
struct InstructionRatio {
    f32: u64,
    other: u64,
    ratio: f64,
}

struct CaseResult {
    case: Case,
    rounds: usize,
    numbers: Vec<Measured>,
}

impl CaseResult {
    fn of(&self, number: NumberKind) -> Option<&Measured> {
        self.numbers.iter().find(|measured| measured.number == number)
    }

    fn f64_median(&self) -> Option<Duration> {
        self.of(NumberKind::F64).and_then(|measured| measured.median)
    }
}

pub fn run(args: &super::BenchArgs) -> anyhow::Result<()> {
    let report_path = args.out.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_REPORT));
    let plot_path = args.plot.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_PLOT));
    let firmware_path = args.firmware_report.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_FIRMWARE_REPORT));
    let firmware = match FirmwareFigures::read(&firmware_path) {
        Ok(figures) => FirmwareSource { figures, path: firmware_path, problem: None },
        Err(problem) => {
            eprintln!("warning: firmware figures not used: {problem}");
            FirmwareSource { figures: FirmwareFigures::default(), path: firmware_path, problem: Some(problem) }
        }
    };
    let started = std::time::Instant::now();
    let (cases, unreadable) = cases(&args.scenes)?;
    let mut results = Vec::new();
    for (position, case) in cases.into_iter().enumerate() {
        eprintln!("[{}] {} ({})", position + 1, case.label(), case.group);
        results.push(measure(case)?);
    }
    let plot_points = plot_points(&results);
    let board_points = board_points(&results, &firmware.figures);
    let mut report = String::new();
    write_report(&mut report, &results, &unreadable, &firmware, &report_path, &plot_path, started.elapsed())?;
    if let Ok(existing) = std::fs::read_to_string(&report_path) {
        if let Some(at) = existing.find(HAND_WRITTEN_HEADING) {
            report.push('\n');
            report.push_str(&existing[at..]);
        }
    }
    print!("{report}");
    if let Some(directory) = report_path.parent().filter(|directory| !directory.as_os_str().is_empty()) {
        std::fs::create_dir_all(directory).with_context(|| format!("cannot create {}", directory.display()))?;
    }
    files::write_atomically(&report_path, |out| out.write_all(report.as_bytes()))
        .with_context(|| format!("cannot write {}", report_path.display()))?;
    plot::write(&plot_path, &plot_points, &GROUPS, &board_points, &BOARD_PANELS)?;
    eprintln!("wrote {} and {}", report_path.display(), plot_path.display());
    Ok(())
}

/// The thesis scenes at both sizes, then every `.mts` in `scenes/hard/` (sorted) at its own
/// size. Hard scenes that cannot be read are returned with their error, to be reported.
fn cases(scenes: &Path) -> anyhow::Result<(Vec<Case>, Vec<UnreadableScene>)> {
    let mut cases = Vec::new();
    for (group, resize) in [(GROUP_FULL, false), (GROUP_SMALL, true)] {
        for file in THESIS_SCENES {
            let mut scene = scene_file::load(&scenes.join(file))?;
            if resize {
                scene.fit_to_size(SMALL_SIZE.0, SMALL_SIZE.1);
            }
            cases.push(Case { group, stem: stem_of(Path::new(file)), scene });
        }
    }
    let hard = scenes.join("hard");
    let mut unreadable = Vec::new();
    let mut hard_files: Vec<PathBuf> = match std::fs::read_dir(&hard) {
        Ok(entries) => entries
            .map(|entry| entry.map(|entry| entry.path()))
            .collect::<Result<Vec<_>, _>>()
            .with_context(|| format!("cannot list {}", hard.display()))?
            .into_iter()
            .filter(|path| path.extension().is_some_and(|extension| extension == "mts"))
            .collect(),
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => {
            eprintln!("warning: {} does not exist: no hard cases", hard.display());
            Vec::new()
        }
        Err(error) => return Err(error).with_context(|| format!("cannot list {}", hard.display())),
    };
    hard_files.sort();
    for path in hard_files {
        match scene_file::load(&path) {
            Ok(scene) => cases.push(Case { group: GROUP_HARD, stem: stem_of(&path), scene }),
            Err(error) => {
                eprintln!("warning: {error:#}");
                unreadable.push(UnreadableScene { stem: stem_of(&path), error: format!("{error:#}") });
            }
        }
    }
    Ok((cases, unreadable))
}

fn stem_of(path: &Path) -> String {
    path.file_stem().map(|stem| stem.to_string_lossy().into_owned()).unwrap_or_default()
}

/// Renders `case` with every number type in interleaved rounds and compares with f64.
fn measure(case: Case) -> anyhow::Result<CaseResult> {
    let mut outcomes: Vec<(NumberKind, Outcome)> = Vec::new();
    let mut first_round = Duration::ZERO;
    for number in NumberKind::ALL {
        let outcome = match timed_render(&case.scene, number) {
            Ok((rendered, time)) => {
                first_round += time;
                match rendered.pixels {
                    Pixels::Pga(indices) => Outcome::Rendered { indices, times: vec![time] },
                    Pixels::Rgb(_) => Outcome::Failed("rendered RGB where palette indices were asked for".into()),
                }
            }
            Err(error) => match error.downcast_ref::<SceneError>() {
                Some(SceneError { kind: SceneErrorKind::OutOfRangeForNumberType { .. }, .. }) => Outcome::OutOfRange(format!("{error:#}")),
                _ => Outcome::Failed(format!("{error:#}")),
            },
        };
        if let Outcome::OutOfRange(message) | Outcome::Failed(message) = &outcome {
            eprintln!("    {}: {message}", number.name());
        }
        outcomes.push((number, outcome));
    }
    let rounds = (ROUND_BUDGET.as_secs_f64() / first_round.as_secs_f64().max(1e-6)) as usize;
    let rounds = rounds.clamp(MIN_ROUNDS, MAX_ROUNDS);
    eprintln!("    first round {:.1} ms; timing {rounds} rounds", first_round.as_secs_f64() * 1e3);
    for _ in 1..rounds {
        for (number, outcome) in outcomes.iter_mut() {
            if let Outcome::Rendered { times, .. } = outcome {
                let (_, time) = timed_render(&case.scene, *number)?;
                times.push(time);
            }
        }
    }
    let reference = match &outcomes[0] {
        (NumberKind::F64, Outcome::Rendered { indices, .. }) => Some(indices.clone()),
        _ => None,
    };
    let (width, height) = (usize::from(case.scene.viewport.width()), usize::from(case.scene.viewport.height()));
    let mut numbers = Vec::new();
    for (number, outcome) in outcomes {
        let (difference, median) = match (&outcome, &reference) {
            (Outcome::Rendered { indices, times }, Some(reference)) => {
                let difference = ImageDifference::measure(reference, indices, width, height, &case.scene.palette)
                    .map_err(|problem| anyhow::anyhow!("{}: {problem}", case.label()))?;
                (Some(difference), Some(median(times)))
            }
            (Outcome::Rendered { times, .. }, None) => (None, Some(median(times))),
            _ => (None, None),
        };
        if let Some(difference) = &difference {
            eprintln!(
                "    {:<14} {:>9.4}% differing, {:>7.2} ms",
                number.name(),
                difference.percent_differing(),
                median.unwrap_or_default().as_secs_f64() * 1e3
            );
        }
        numbers.push(Measured { number, outcome, difference, median });
    }
    Ok(CaseResult { case, rounds, numbers })
}

/// Renders in PGA mode and times preparation plus tracing in the thread's CPU time (wall-clock
/// time where there is no thread clock).
fn timed_render(scene: &HostScene, number: NumberKind) -> anyhow::Result<(crate::rendering::Rendered, Duration)> {
    let started = clock::thread_cpu_time();
    // `render_scene` renders on this thread alone, so this thread's CPU time is the whole render's.
    let rendered = render_scene(scene, number, Mode::Pga, None)?;
    let time = match (started, clock::thread_cpu_time()) {
        (Some(started), Some(finished)) => finished.saturating_sub(started),
        _ => rendered.preprocess + rendered.trace,
    };
    Ok((rendered, time))
}

fn median(times: &[Duration]) -> Duration {
    let mut sorted = times.to_vec();
    sorted.sort();
    match sorted.len() {
        0 => Duration::ZERO,
        n if n % 2 == 1 => sorted[n / 2],
        n => (sorted[n / 2 - 1] + sorted[n / 2]) / 2,
    }
}

/// One point per number type per group: differing pixels over all the group's pixels, and
/// the sum of the median times over the sum of f64's, over the scenes the type could render.
fn plot_points(results: &[CaseResult]) -> Vec<PlotPoint> {
    let mut points = Vec::new();
    for group in GROUPS {
        for number in NumberKind::ALL {
            let (mut differing, mut pixels, mut time, mut f64_time) = (0, 0, 0.0, 0.0);
            for result in results.iter().filter(|result| result.case.group == group) {
                let (Some(measured), Some(reference_time)) = (result.of(number), result.f64_median()) else { continue };
                let (Some(difference), Some(median)) = (&measured.difference, measured.median) else { continue };
                differing += difference.differing;
                pixels += difference.pixels;
                time += median.as_secs_f64();
                f64_time += reference_time.as_secs_f64();
            }
            if pixels > 0 && f64_time > 0.0 {
                points.push(PlotPoint {
                    number: number.name(),
                    group,
                    time_relative_to_f64: time / f64_time,
                    percent_differing: percent(differing, pixels),
                });
            }
        }
    }
    points
}

/// The board panels of the plot, two to a row: the cores without an FPU (M0, M3), then those
/// with one (M4F, M33).
const BOARD_PANELS: [BoardPanel; 4] = [
    BoardPanel { title: "Cortex-M0 (microbit, RP2040's ISA): firmware", board: CORTEX_M0_BOARD },
    BoardPanel { title: "Cortex-M3 (lm3s6965evb, no FPU): firmware", board: CORTEX_M3_BOARD },
    BoardPanel { title: "Cortex-M4F (mps2-an386): firmware", board: CORTEX_M4F_BOARD },
    BoardPanel { title: "Cortex-M33 (mps2-an505, RP2350's core): firmware", board: CORTEX_M33_BOARD },
];

/// One point per board, thesis scene and number type: the firmware's instructions per 128x64
/// frame (`frame_instructions`, or `instructions` in an older report) against the share of
/// pixels of the host's 128x64 render in that type that differ from f64's (the firmware renders
/// the same bytes; tests/tests/firmware_qemu.rs checks it). f64 is a point too, at 0 %.
fn board_points(results: &[CaseResult], firmware: &FirmwareFigures) -> Vec<BoardPoint> {
    let small_pixels = u32::from(SMALL_SIZE.0) * u32::from(SMALL_SIZE.1);
    let mut points = Vec::new();
    for panel in BOARD_PANELS {
        for result in results.iter().filter(|r| r.case.group == GROUP_SMALL && r.case.scene.viewport.pixel_count() == small_pixels) {
            for measured in &result.numbers {
                let (Some(difference), name) = (&measured.difference, measured.number.name()) else { continue };
                let Some(per_frame) = firmware.instructions_per_frame(&result.case.stem, panel.board, name) else { continue };
                points.push(BoardPoint {
                    board: panel.board,
                    scene: result.case.stem.clone(),
                    number: name,
                    instructions_per_frame: per_frame.instructions,
                    whole_frame: per_frame.whole_frame,
                    percent_differing: difference.percent_differing(),
                });
            }
        }
    }
    points
}

/// A verdict for the summary.
fn verdict(met: Option<bool>) -> &'static str {
    match met {
        Some(true) => "**met**",
        Some(false) => "**NOT met**",
        None => "not measured",
    }
}

fn write_report(
    report: &mut String,
    results: &[CaseResult],
    unreadable: &[UnreadableScene],
    firmware: &FirmwareSource,
    report_path: &Path,
    plot_path: &Path,
    elapsed: Duration,
) -> anyhow::Result<()> {
    writeln!(report, "# Number types: speed against error\n")?;
    writeln!(
        report,
        "Generated by `microtrace bench --numbers` (`cargo run --release -p microtrace-sim -- bench --numbers`); \
         do not edit above the hand-written notes at the end, the next run rewrites it. Host: {} {}, {} hardware threads.\n",
        std::env::consts::OS,
        std::env::consts::ARCH,
        std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1)
    )?;
    write_summary(report, results, firmware)?;
    write_number_types(report)?;
    write_method(report, results, &firmware.path)?;
    write_usage(report, elapsed)?;
    writeln!(report, "## Speed against error\n")?;
    writeln!(report, "![speed against error]({})\n", relative_link(report_path, plot_path))?;
    writeln!(
        report,
        "Top, the host: one point per number type per scene group: x is the sum of the type's median render times over \
         the group's scenes divided by the same sum for f64; y is the share of the group's pixels whose palette index \
         differs from f64's (log scale; 0 % is drawn on the bottom line). Scenes a type cannot render (out of range) are \
         left out of that type's point.\n"
    )?;
    writeln!(
        report,
        "Below, one panel per board: {CORTEX_M0_BOARD} (Cortex-M0, the RP2040's instruction set: no FPU, no divide, no \
         32x32→64 multiply), {CORTEX_M3_BOARD} (Cortex-M3, no FPU), {CORTEX_M4F_BOARD} (Cortex-M4F) and \
         {CORTEX_M33_BOARD} (Cortex-M33 with an FPU, the RP2350's core): one point \
         per number type per thesis scene: x is the firmware's instructions for one {}x{} frame, preparation plus \
         render (`frame_instructions` of the firmware report, or its `instructions` where it has none; log scale), y \
         the same share of differing pixels as above for that scene at {}x{} (the firmware renders the host's bytes). \
         Lower and further left is better: the type for a board is read off its panel. A report from before the frame \
         was measured counts the render alone; the axis says so when a point's count is such.\n",
        SMALL_SIZE.0,
        SMALL_SIZE.1,
        SMALL_SIZE.0,
        SMALL_SIZE.1
    )?;
    for group in GROUPS {
        write_group_table(report, results, group, &firmware.figures)?;
    }
    if !unreadable.is_empty() {
        writeln!(report, "Hard-case files that could not be read (not rendered):\n")?;
        for scene in unreadable {
            writeln!(report, "- `{}`: {}", scene.stem, one_line(&scene.error))?;
        }
        writeln!(report)?;
    }
    write_firmware_source(report, firmware)?;
    Ok(())
}

fn write_summary(report: &mut String, results: &[CaseResult], firmware: &FirmwareSource) -> anyhow::Result<()> {
    let firmware_path = &firmware.path;
    writeln!(report, "## Summary: the targets of issue 4\n")?;
    writeln!(report, "| target | measured | verdict |\n|---|---|---|")?;
    let thesis: Vec<&CaseResult> = results.iter().filter(|r| r.case.group != GROUP_HARD).collect();
    let differences = |number: NumberKind| -> Vec<(String, Option<ImageDifference>)> {
        thesis.iter().map(|r| (r.case.label(), r.of(number).and_then(|m| m.difference))).collect()
    };
    let all_met = |values: &[(String, Option<ImageDifference>)], test: &dyn Fn(&ImageDifference) -> bool| -> Option<bool> {
        values.iter().map(|(_, d)| d.as_ref().map(test)).collect::<Option<Vec<bool>>>().map(|v| v.iter().all(|ok| *ok))
    };
    let list = |values: &[(String, Option<ImageDifference>)], show: &dyn Fn(&ImageDifference) -> String| -> String {
        values
            .iter()
            .map(|(label, d)| format!("{label}: {}", d.as_ref().map_or("not rendered".into(), show)))
            .collect::<Vec<_>>()
            .join("; ")
    };
    let fixed = differences(NumberKind::Fixed);
    let f32 = differences(NumberKind::F32);
    let identical = |d: &ImageDifference| identical_text(d);
    writeln!(
        report,
        "| fixed (Q32.32): ≥ {FIXED_IDENTICAL_PERCENT} % of pixels identical to f64 on both thesis scenes at their own size and 128x64 | {} | {} |",
        list(&fixed, &identical),
        verdict(all_met(&fixed, &|d| d.percent_identical() >= FIXED_IDENTICAL_PERCENT))
    )?;
    writeln!(
        report,
        "| fixed: no pixel more than {FIXED_LARGEST_SHADE_STEP} shade step from f64 (a change of colour group counts as more) | {} | {} |",
        list(&fixed, &|d| format!("largest step {}, group changes {}", d.largest_shade_step, d.group_changes)),
        verdict(all_met(&fixed, &|d| d.largest_shade_step <= FIXED_LARGEST_SHADE_STEP && d.group_changes == 0))
    )?;
    writeln!(
        report,
        "| fixed: no speckles | {} | {} |",
        list(&fixed, &|d| d.speckles.to_string()),
        verdict(all_met(&fixed, &|d| d.speckles == 0))
    )?;
    writeln!(
        report,
        "| f32: ≥ {F32_IDENTICAL_PERCENT} % identical to f64 on both thesis scenes, both sizes | {} | {} |",
        list(&f32, &identical),
        verdict(all_met(&f32, &|d| d.percent_identical() >= F32_IDENTICAL_PERCENT))
    )?;
    let stems: Vec<&str> = THESIS_SCENES.iter().map(|file| file.trim_end_matches(".mts")).collect();
    let ratio_in = |build: Build, stem: &str, number: &str| -> Option<InstructionRatio> {
        let f32 = firmware.figures.instructions_per_pixel_of(build, stem, CORTEX_M3_BOARD, "f32")?;
        let other = firmware.figures.instructions_per_pixel_of(build, stem, CORTEX_M3_BOARD, number)?;
        Some(InstructionRatio { f32, other, ratio: f32 as f64 / other.max(1) as f64 })
    };
    let ratio = |stem: &str, number: &str| ratio_in(Build::SceneOptimizations, stem, number);
    // The speed target for `number`, over the thesis scenes in each of `builds` (labelled).
    let speed_target = |number: &str, builds: &[(Build, &str)]| -> (String, Option<bool>) {
        let ratios: Vec<(String, Option<InstructionRatio>)> = builds
            .iter()
            .flat_map(|(build, label)| stems.iter().map(move |stem| (*build, *label, *stem)))
            .map(|(build, label, stem)| {
                let name = if label.is_empty() { stem.to_owned() } else { format!("{stem}, {label}") };
                (name, ratio_in(build, stem, number))
            })
            .collect();
        let measured = ratios
            .iter()
            .map(|(label, r)| match r {
                Some(r) => format!("{label}: f32 {} / {number} {} = {:.2}x", r.f32, r.other, r.ratio),
                None => format!("{label}: no entry in {}", firmware_path.display()),
            })
            .collect::<Vec<_>>()
            .join("; ");
        let met = ratios.iter().map(|(_, r)| r.map(|r| r.ratio >= CORTEX_M3_FIXED_SPEEDUP)).collect::<Option<Vec<bool>>>();
        (measured, met.map(|v| v.iter().all(|ok| *ok)))
    };
    let (measured, speedup_met) = speed_target("fixed", &[(Build::SceneOptimizations, "")]);
    writeln!(
        report,
        "| Cortex-M3: fixed needs ≥ {CORTEX_M3_FIXED_SPEEDUP}x fewer instructions per pixel than f32 (128x64, thesis scenes) | {measured} | {} |",
        verdict(speedup_met)
    )?;
    // soft32, the software floating point, against f32's accuracy target and the same speed
    // target, with the scene's optimizations and with all of them off.
    let soft = differences(NumberKind::Soft32);
    writeln!(
        report,
        "| soft32 (software floating point): f32's target, ≥ {F32_IDENTICAL_PERCENT} % identical to f64 on both thesis scenes, both sizes | {} | {} |",
        list(&soft, &identical),
        verdict(all_met(&soft, &|d| d.percent_identical() >= F32_IDENTICAL_PERCENT))
    )?;
    let (soft_measured, soft_speedup_met) =
        speed_target("soft32", &[(Build::SceneOptimizations, "scene's optimizations"), (Build::OptimizationsOff, "optimizations off")]);
    writeln!(
        report,
        "| Cortex-M3: soft32 needs ≥ {CORTEX_M3_FIXED_SPEEDUP}x fewer instructions per pixel than f32 (128x64, thesis scenes) | {soft_measured} | {} |",
        verdict(soft_speedup_met)
    )?;
    writeln!(report)?;
    write_accuracy_overview(report, &thesis)?;
    // Plain words for what is not met.
    let fixed16 = differences(NumberKind::Fixed16);
    let fixed16_speedups: Vec<String> = stems
        .iter()
        .filter_map(|stem| ratio(stem, "fixed16").map(|r| format!("{stem} {:.2}x", r.ratio)))
        .collect();
    if speedup_met == Some(false) {
        writeln!(
            report,
            "**Not met: the Cortex-M3 speed target.** Q32.32 (`fixed`) needs only the ratio above fewer instructions per pixel than software f32, short of \
             {CORTEX_M3_FIXED_SPEEDUP}x: its additions and dot products are cheaper than software f32's, its \
             multiplies (four 32x32→64 partial products) about the same, and its division and square root dearer \
             (per-operation counts in core/src/number/fixed.rs). Q16.16 (`fixed16`), whose additions and multiplies \
             are far cheaper still, needs {} fewer, so much of a pixel's cost is not in the arithmetic the type \
             changes; and it {} fixed's accuracy targets: {}.\n",
            if fixed16_speedups.is_empty() { "(no firmware figures)".into() } else { fixed16_speedups.join(", ") },
            match all_met(&fixed16, &|d| {
                d.percent_identical() >= FIXED_IDENTICAL_PERCENT
                    && d.largest_shade_step <= FIXED_LARGEST_SHADE_STEP
                    && d.group_changes == 0
                    && d.speckles == 0
            }) {
                Some(true) => "meets",
                Some(false) => "misses",
                None => "was not measured against",
            },
            list(&fixed16, &|d| format!(
                "{} identical, largest step {}, {} group changes, {} speckles",
                identical_text(d),
                d.largest_shade_step,
                d.group_changes,
                d.speckles
            ))
        )?;
        let unoptimized: Vec<String> = stems
            .iter()
            .flat_map(|stem| ["fixed", "fixed16"].map(|number| (stem, number)))
            .filter_map(|(stem, number)| {
                ratio_in(Build::OptimizationsOff, stem, number)
                    .map(|r| format!("{stem} f32 {} / {number} {} = {:.2}x", r.f32, r.other, r.ratio))
            })
            .collect();
        if !unoptimized.is_empty() {
            writeln!(
                report,
                "With every optimization off (every ray tests every object: the firmware report's \
                 `optimizations: none` builds, Cortex-M3): {}.\n",
                unoptimized.join("; ")
            )?;
        }
    } else if speedup_met.is_none() {
        writeln!(
            report,
            "The Cortex-M3 target cannot be judged from this run: {} lacks f32 or fixed figures for a thesis scene on \
             {CORTEX_M3_BOARD} (run `cargo xtask firmware-report`, then this command again).\n",
            firmware_path.display()
        )?;
    }
    Ok(())
}

/// Every type against fixed's accuracy targets, worst case over the thesis scenes at both sizes.
fn write_accuracy_overview(report: &mut String, thesis: &[&CaseResult]) -> anyhow::Result<()> {
    writeln!(
        report,
        "Every type against fixed's accuracy targets (≥ {FIXED_IDENTICAL_PERCENT} % identical, no step above \
         {FIXED_LARGEST_SHADE_STEP}, no group change, no speckle), worst case over the {} thesis renders above:\n",
        thesis.len()
    )?;
    writeln!(report, "| number | lowest identical | largest step | group changes | speckles | all four met |\n|---|---:|---:|---:|---:|---|")?;
    for &number in &NumberKind::ALL[1..] {
        let differences: Option<Vec<ImageDifference>> = thesis.iter().map(|r| r.of(number).and_then(|m| m.difference)).collect();
        let Some(differences) = differences.filter(|d| !d.is_empty()) else {
            writeln!(report, "| {} | not rendered on every thesis scene | | | | not measured |", number.name())?;
            continue;
        };
        let worst = differences.iter().min_by(|a, b| a.percent_identical().total_cmp(&b.percent_identical())).copied().unwrap_or(differences[0]);
        let step = differences.iter().map(|d| d.largest_shade_step).max().unwrap_or(0);
        let group_changes: usize = differences.iter().map(|d| d.group_changes).sum();
        let speckles: usize = differences.iter().map(|d| d.speckles).sum();
        let met = worst.percent_identical() >= FIXED_IDENTICAL_PERCENT
            && step <= FIXED_LARGEST_SHADE_STEP
            && group_changes == 0
            && speckles == 0;
        writeln!(
            report,
            "| {} | {} | {step} | {group_changes} | {speckles} | {} |",
            number.name(),
            identical_text(&worst),
            if met { "yes" } else { "**no**" }
        )?;
    }
    writeln!(report)?;
    Ok(())
}

fn write_number_types(report: &mut String) -> anyhow::Result<()> {
    writeln!(report, "## The number types\n")?;
    writeln!(
        report,
        "`--number` chooses the type every per-pixel computation runs in, in every command that has it \
         (`render`, `view`, where N cycles them, and the firmware's `cargo xtask firmware --number`). \
         Scene set-up (matrix inversion, trigonometry) is always f64 and converted once.\n"
    )?;
    writeln!(report, "| `--number` | representation | range of scene values | notes |\n|---|---|---|---|")?;
    for number in NumberKind::ALL {
        let (representation, notes) = match number {
            NumberKind::F64 => ("IEEE binary64", "the reference every other type is compared with"),
            NumberKind::F32 => ("IEEE binary32", "hardware on Cortex-M4F, software on Cortex-M3"),
            NumberKind::Fixed => (
                "Q32.32 in an i64 (fixed point)",
                "exact 128-bit products rounded once; for FPU-less targets; saturates instead of overflowing",
            ),
            NumberKind::Fixed16 => (
                "Q16.16 in an i32 (fixed point)",
                "64-bit intermediate products; cheapest on Cortex-M3, but unit directions keep only 16 fraction bits",
            ),
            NumberKind::F32Micromath => ("IEEE binary32", "micromath's approximate square root (up to 6 % error)"),
            NumberKind::Soft32 => (
                "28-bit mantissa and binary exponent in two i32 (software floating point)",
                "for FPU-less targets: no NaN, infinity or denormals; saturates; products by one 32x32 multiply, sums and dot products in 32-bit registers",
            ),
        };
        writeln!(report, "| `{}` | {representation} | {} | {notes} |", number.name(), scene_limit(number))?;
    }
    writeln!(report)?;
    Ok(())
}

/// The largest scene value the type accepts (`Number::SCENE_LIMIT`).
fn scene_limit(number: NumberKind) -> String {
    use microtrace::number::Number;
    let limit = microtrace::with_number_kind!(number, N => <N as Number>::SCENE_LIMIT);
    if limit.is_infinite() { "any finite".into() } else { format!("±{limit}") }
}

fn write_method(report: &mut String, results: &[CaseResult], firmware_path: &Path) -> anyhow::Result<()> {
    let rounds: Vec<usize> = results.iter().map(|r| r.rounds).collect();
    let (fewest, most) = (rounds.iter().min().copied().unwrap_or(0), rounds.iter().max().copied().unwrap_or(0));
    writeln!(report, "## What is measured\n")?;
    writeln!(
        report,
        "Scenes: `snooker.mts` and `lattice.mts` at their own size and fitted to {}x{} (`--size`), and every `.mts` \
         file in `scenes/hard/` at its own size. Every scene is rendered in PGA mode with its own settings \
         (optimizations, shadows, dither) with every number type, and each image is compared with the f64 image of \
         the same scene:\n",
        SMALL_SIZE.0,
        SMALL_SIZE.1
    )?;
    writeln!(report, "- **identical**: the share of pixels whose palette index equals f64's.")?;
    writeln!(
        report,
        "- **largest step**: the largest |shade − f64's shade| (shade = index & 15) over the pixels whose colour group \
         (index >> 4) is the same as f64's."
    )?;
    writeln!(
        report,
        "- **group changes**: pixels whose colour group differs from f64's (another object or the background: a \
         moved silhouette or a flipped shadow test); counted here, not as shade steps."
    )?;
    writeln!(
        report,
        "- **speckles**: pixels whose index differs from f64's *and* differs from the index of every one of their \
         neighbours in the type's own image (eight neighbours; five on an edge, three in a corner): isolated wrong \
         pixels that a viewer sees as noise."
    )?;
    writeln!(
        report,
        "- **PSNR**: 10·log10(255² / MSE) in dB, MSE over the three 8-bit channels of every pixel of the two images \
         taken through the scene's look-up table; ∞ when the images are identical."
    )?;
    writeln!(
        report,
        "- **time**: scene preparation plus tracing on this host in the thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`: \
         time spent waiting while other programs hold the cores is not counted), the median of {fewest}–{most} rounds (as many as fit \
         about {} s per scene, at least {MIN_ROUNDS}; the column `rounds` says how many) in which the types take turns \
         (f64, f32, fixed, …, then again), so all types see the same machine load; **/ f64** divides by f64's median \
         of the same run.",
        ROUND_BUDGET.as_secs()
    )?;
    writeln!(
        report,
        "- **M3, M4F instructions per pixel**: from `{}` (see the end of this report), 128x64 renders; — where it has \
         no entry.\n",
        firmware_path.display()
    )?;
    Ok(())
}

fn write_usage(report: &mut String, elapsed: Duration) -> anyhow::Result<()> {
    writeln!(report, "## Running it\n")?;
    writeln!(
        report,
        "`microtrace bench --numbers [--scenes DIR] [--out FILE.md] [--plot FILE.png] [--firmware-report FILE.json]` \
         reads the thesis scenes and `hard/*.mts` from `--scenes` (default `scenes`), writes this report to `--out` \
         (default `{DEFAULT_REPORT}`) and stdout and the plot to `--plot` (default `{DEFAULT_PLOT}`), and reads the \
         Cortex-M figures from `--firmware-report` (default `{DEFAULT_FIRMWARE_REPORT}`; a missing file leaves those \
         columns empty). A hard-case file that cannot be read is listed, not skipped; a scene beyond a type's range \
         shows as **out of range** with the preparation error. Progress goes to stderr. The section under \
         \"{}\" at the end of an existing report is kept. This run took {:.0} s (release build).\n",
        HAND_WRITTEN_HEADING.trim_start_matches("## "),
        elapsed.as_secs_f64()
    )?;
    Ok(())
}

fn write_group_table(report: &mut String, results: &[CaseResult], group: &str, firmware: &FirmwareFigures) -> anyhow::Result<()> {
    let in_group: Vec<&CaseResult> = results.iter().filter(|r| r.case.group == group).collect();
    writeln!(report, "## {}{}\n", group[..1].to_uppercase(), &group[1..])?;
    if in_group.is_empty() {
        writeln!(report, "No scenes in this group in this run.\n")?;
        return Ok(());
    }
    let small = group != GROUP_FULL;
    writeln!(
        report,
        "| scene | number | identical | group changes | largest step | speckles | PSNR | time | / f64 | rounds | M0 instr/px | M3 instr/px | M4F instr/px | M33 instr/px |"
    )?;
    writeln!(report, "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")?;
    for result in in_group {
        let f64_median = result.f64_median();
        for measured in &result.numbers {
            let name = measured.number.name();
            let instructions = |board: &str| {
                let at_128x64 = small && result.case.scene.viewport.pixel_count() == u32::from(SMALL_SIZE.0) * u32::from(SMALL_SIZE.1);
                at_128x64
                    .then(|| firmware.instructions_per_pixel(&result.case.stem, board, name))
                    .flatten()
                    .map_or("—".into(), |n| n.to_string())
            };
            let scene = result.case.label();
            match (&measured.outcome, &measured.difference) {
                (Outcome::Rendered { .. }, Some(d)) => {
                    let time = measured.median.unwrap_or_default();
                    let relative = f64_median.map_or("—".into(), |f| format!("{:.2}", time.as_secs_f64() / f.as_secs_f64().max(1e-12)));
                    let psnr = if d.psnr_db.is_infinite() { "∞".into() } else { format!("{:.1} dB", d.psnr_db) };
                    writeln!(
                        report,
                        "| {scene} | {name} | {} | {} | {} | {} | {psnr} | {:.2} ms | {relative} | {} | {} | {} | {} | {} |",
                        identical_text(d),
                        d.group_changes,
                        d.largest_shade_step,
                        d.speckles,
                        time.as_secs_f64() * 1e3,
                        result.rounds,
                        instructions(CORTEX_M0_BOARD),
                        instructions(CORTEX_M3_BOARD),
                        instructions(CORTEX_M4F_BOARD),
                        instructions(CORTEX_M33_BOARD)
                    )?;
                }
                (Outcome::Rendered { .. }, None) => {
                    writeln!(report, "| {scene} | {name} | no f64 image to compare with | | | | | | | | | | | |")?;
                }
                (Outcome::OutOfRange(message), _) => {
                    writeln!(report, "| {scene} | {name} | **out of range**: {} | | | | | | | | | | | |", one_line(message))?;
                }
                (Outcome::Failed(message), _) => {
                    writeln!(report, "| {scene} | {name} | **failed**: {} | | | | | | | | | | | |", one_line(message))?;
                }
            }
        }
    }
    writeln!(report)?;
    Ok(())
}

fn write_firmware_source(report: &mut String, firmware: &FirmwareSource) -> anyhow::Result<()> {
    writeln!(report, "## Where the Cortex-M figures come from\n")?;
    let source = format!(
        "Instructions per pixel and per frame are read from `{}`, which `cargo xtask firmware-report` writes: each \
         thesis scene rendered at 128x64 by the firmware under QEMU with an instruction-counting plugin, Cortex-M0 on \
         the {CORTEX_M0_BOARD} board and Cortex-M3 on {CORTEX_M3_BOARD} (no FPU: f32 in software), Cortex-M4F on \
         {CORTEX_M4F_BOARD} and Cortex-M33 on {CORTEX_M33_BOARD} (single-precision FPU). They count the frame, the scene's preparation plus the render, as the host's times do (a report without \
         `frame_instructions` is from before the frame was measured and counts the render alone). They are \
         instructions, not cycles.",
        firmware.path.display()
    );
    match &firmware.problem {
        Some(problem) => writeln!(report, "{source} This run could not use it: {}.\n", one_line(problem))?,
        None if firmware.figures.is_empty() => writeln!(report, "{source} It did not exist when this report was made, so those columns are empty.\n")?,
        None => writeln!(report, "{source}\n")?,
    }
    Ok(())
}

/// The identical share to three decimals, rounded down so that an image with a differing pixel
/// never reads as 100.000 %.
fn identical_text(difference: &ImageDifference) -> String {
    format!("{:.3} %", (difference.percent_identical() * 1000.0).floor() / 1000.0)
}

/// A message on one line, with the characters that would break a Markdown table escaped.
fn one_line(message: &str) -> String {
    message.replace('\n', " ").replace('|', "\\|")
}

/// The plot's path as a link from the report's directory, when the plot is under it.
fn relative_link(report_path: &Path, plot_path: &Path) -> String {
    let directory = report_path.parent().unwrap_or(Path::new(""));
    plot_path.strip_prefix(directory).unwrap_or(plot_path).display().to_string()
}
