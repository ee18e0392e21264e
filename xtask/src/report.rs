//! `cargo xtask firmware-report`: the firmware's cost and footprint for both thesis scenes at
//! 128x64, every number type and every board (a Cortex-M0, M3, M4F and M33), plus all-primitives
//! builds to set against the scene-only ones. Every run's picture is set against the host's
//! render in the same number type (`host_render`); a build the board's RAM cannot hold is listed
//! with what it needs. Writes the Markdown table into docs/firmware-report.md (between
//! [`START_MARKER`] and [`END_MARKER`]) and `docs/firmware-report.json`, which
//! `microtrace bench --numbers` reads.

use std::path::PathBuf;

use crate::budget;
use crate::example;
use crate::firmware::{self, Board, FirmwareOptions, Primitives, NUMBERS};
use crate::pico;

pub const START_MARKER: &str = "<!-- firmware-report:start -->";
pub const END_MARKER: &str = "<!-- firmware-report:end -->";
/// The section the markers go in when docs/firmware-report.md has none yet.
const SECTION_HEADING: &str = "## The firmware: cost and footprint";

const SCENES: [&str; 2] = ["scenes/snooker.mts", "scenes/lattice.mts"];
/// The scenes beyond chapter 4: chapter 5's (the ray tree, antialiasing), the torus §5.2.1
/// proposes and the solids of chapter 3 (scenes/csg), run with their own `optimize` in these number
/// types only: what the tree, the corners, the quartic and the walk of a solid cost on each
/// board.
const CHAPTER_FIVE_SCENES: [&str; 7] =
    ["scenes/snooker-polished.mts", "scenes/lattice-antialiased.mts", "scenes/torus.mts", "scenes/csg/die.mts", "scenes/csg/lens.mts", "scenes/csg/cup.mts", "scenes/csg/nut.mts"];

/// A scene file's name as the report's runs name it: `scenes/csg/die.mts` is `die`.
fn stem(file: &str) -> &str {
    file.rsplit('/').next().unwrap_or(file).trim_end_matches(".mts")
}
const CHAPTER_FIVE_NUMBERS: [&str; 2] = ["f32", "soft32"];
/// The all-primitives builds are compared in this number type only: code size, not arithmetic.
const ALL_PRIMITIVES_NUMBER: &str = "f32";

/// One firmware run, as `docs/firmware-report.json` holds it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReportRun {
    /// The scene file's stem (`snooker`).
    pub scene: String,
    pub board: Board,
    pub number: String,
    pub primitives: Primitives,
    /// `scene` (the scene's own `optimize`) or `none` (every optimization off, so the
    /// intersection arithmetic, where the number types differ, dominates).
    pub optimizations: &'static str,
    pub width: u64,
    pub height: u64,
    /// The frame's (preparation plus render), as `frame_instructions`.
    pub instructions: u64,
    pub frame_instructions: u64,
    /// From the start marker to the render marker: preparing the scene, setting up the sink.
    pub prepare_instructions: u64,
    /// From the render marker to the end marker.
    pub render_instructions: u64,
    pub pixels: u64,
    /// The frame's instructions per pixel.
    pub instructions_per_pixel: u64,
    pub flash_bytes: u64,
    pub static_ram_bytes: u64,
    pub stack_peak_bytes: u64,
    /// The linked-code audit's counts (`elf::audit`): double-precision routines, panic paths,
    /// `core::fmt` functions.
    pub f64_symbols: u64,
    pub panic_symbols: u64,
    pub fmt_symbols: u64,
    /// Primary rays (with antialiasing, every corner and sub-corner ray) and the ray tree's.
    pub rays_traced: u64,
    pub secondary_rays: u64,
    /// Pixels of `framebuffer.bin` that differ from the host's render in the same number type
    /// (`host_render`): 0 when the chip and the host agree byte for byte.
    pub differing_pixels: u64,
    /// Where the flash goes (`elf::flash_symbols`): each area's bytes, largest first. Not in the
    /// JSON: docs/firmware-report.md's table gives it for the thesis scenes on the Cortex-M3.
    pub flash_areas: Vec<(String, u64)>,
}

/// A build that the board's RAM cannot hold: the RAM check's message (firmware/src/ram.rs).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ReportMiss {
    pub scene: String,
    pub board: Board,
    pub number: String,
    pub primitives: Primitives,
    pub optimizations: &'static str,
    /// `needs 19,548 bytes of RAM (...), the microbit has 16,384`.
    pub reason: String,
}

/// The RAM check's reason when `error` is a build that failed it.
pub fn does_not_fit(error: &str) -> Option<String> {
    let line = error.lines().find(|line| line.contains(" bytes of RAM (") && line.contains("needs "))?;
    let from = line.find("needs ")?;
    let reason = &line[from..];
    Some(reason.split(" (firmware/README.md").next().unwrap_or(reason).to_owned())
}

/// The pixels of a run's `framebuffer.bin` that differ from the host's render of `scene` in
/// the same number type and optimizations (all of them when the sizes differ).
pub fn differing_from_host(result: &firmware::FirmwareRun, scene: &std::path::Path, number: &str, optimizations: &str) -> Result<u64, String> {
    let framebuffer = std::fs::read(&result.framebuffer).map_err(|error| format!("{}: {error}", result.framebuffer.display()))?;
    let host = crate::host_render::render(scene, number, optimizations).map_err(|error| format!("the host render: {error}"))?;
    Ok(if framebuffer.len() == host.len() { framebuffer.iter().zip(&host).filter(|(chip, host)| chip != host).count() as u64 } else { host.len() as u64 })
}

/// A real-board example's image (the UF2 file a user flashes) run in the rp2040js emulator
/// (`crate::pico`): snooker in `f32` at its display's size, from reset to the last display byte.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExampleRun {
    /// The example's folder under firmware/examples/.
    pub example: &'static str,
    pub chip: &'static str,
    pub core: &'static str,
    pub width: u64,
    pub height: u64,
    /// Emulated cycles from reset (the boot ROM, boot2, parsing and preparing the scene
    /// included) to the last byte sent to the display.
    pub cycles: u64,
    /// Of those, the cycles from reset to the first entry into the example's `render`: the
    /// set-up (boot, clocks, display, parsing and preparing the scene). The rest is the render
    /// with its display traffic.
    pub setup_cycles: u64,
    /// Instructions executed from reset to the last display byte, and before `render`.
    pub instructions: u64,
    pub setup_instructions: u64,
    pub flash_bytes: u64,
    pub static_ram_bytes: u64,
}

/// Every real-board example, run in rp2040js.
fn example_runs() -> Result<Vec<ExampleRun>, String> {
    let mut runs = Vec::new();
    // rp2040js emulates the RP2040 only: the Pico 2's example is built and checked, not run.
    for example in example::EXAMPLES.into_iter().filter(|example| pico::emulation(example).is_some()) {
        println!("[rp2040js] {} ...", example.folder);
        let out = crate::firmware_dir().join("target/report/pico").join(example.folder);
        let run = pico::run(&example, &out)?;
        let elf = example::build(&example)?;
        let bytes = std::fs::read(&elf).map_err(|error| format!("{}: {error}", elf.display()))?;
        let image = example::check_image(&bytes, example.chip, 0, &[]).map_err(|problems| format!("{}: {}", elf.display(), problems.join("; ")))?;
        let size = pico::emulation(&example).map_or((0, 0), |emulation| emulation.size);
        println!("    {} cycles to the last display byte", run.cycles);
        runs.push(ExampleRun {
            example: example.folder,
            chip: example.chip.name,
            core: "Cortex-M0+",
            width: size.0,
            height: size.1,
            cycles: run.cycles,
            setup_cycles: run.render_entered.ok_or_else(|| format!("{}: the harness saw no entry into `render`", example.folder))?,
            instructions: run.instructions.ok_or_else(|| format!("{}: the harness counted no instructions", example.folder))?,
            setup_instructions: run.render_entered_instructions.ok_or_else(|| format!("{}: the harness saw no entry into `render`", example.folder))?,
            flash_bytes: image.flash_bytes,
            static_ram_bytes: image.static_ram_bytes,
        });
    }
    Ok(runs)
}

/// [`json`] with the builds that did not fit (`"did_not_fit"`) and the examples' runs
/// (`"examples"`) after the firmware's.
pub fn json_with_examples(runs: &[ReportRun], misses: &[ReportMiss], examples: &[ExampleRun]) -> String {
    let firmware = json(runs);
    let firmware = firmware.trim_end().trim_end_matches('}');
    let missed: Vec<String> = misses
        .iter()
        .map(|miss| {
            format!(
                "{{\"scene\":\"{}\",\"board\":\"{}\",\"number\":\"{}\",\"primitives\":\"{}\",\"optimizations\":\"{}\",\"reason\":\"{}\"}}",
                miss.scene,
                miss.board.name(),
                miss.number,
                miss.primitives.name(),
                miss.optimizations,
                miss.reason.replace('\\', "\\\\").replace('"', "\\\"")
            )
        })
        .collect();
    let lines: Vec<String> = examples
        .iter()
        .map(|run| {
            format!(
                "{{\"example\":\"{}\",\"chip\":\"{}\",\"core\":\"{}\",\"scene\":\"snooker\",\"number\":\"f32\",\"width\":{},\"height\":{},\"cycles\":{},\"setup_cycles\":{},\"instructions\":{},\"setup_instructions\":{},\"flash_bytes\":{},\"static_ram_bytes\":{}}}",
                run.example, run.chip, run.core, run.width, run.height, run.cycles, run.setup_cycles, run.instructions, run.setup_instructions, run.flash_bytes, run.static_ram_bytes
            )
        })
        .collect();
    format!("{firmware},\n\"did_not_fit\":[\n{}\n],\n\"examples\":[\n{}\n]}}\n", missed.join(",\n"), lines.join(",\n"))
}

/// The examples' table, after the firmware's.
fn examples_markdown(examples: &[ExampleRun]) -> String {
    if examples.is_empty() {
        return String::new();
    }
    let mut text = String::from(
        "\nThe real-board examples (firmware/examples/), each its UF2 file booted in the rp2040js emulator\n\
         from the RP2040's boot ROM (`tests/tests/pico_emulated.rs` checks their pictures against the\n\
         host's): snooker in `f32` at the display's size. **These are cycles**, emulated, from reset\n\
         (the boot ROM, boot2, parsing and preparing the scene) to the last byte sent to the display;\n\
         rp2040js models no flash (XIP) or bus wait states. `set-up` is the cycles before the example's\n\
         `render` is first entered (boot, clocks, the display's set-up, parsing and preparing the scene\n\
         on the device), `render` the rest (the render and its display traffic); the instructions\n\
         executed are counted beside the cycles, as QEMU counts the firmware's.\n\n\
         | example | chip | core | size | cycles | at 125 MHz | set-up cycles | render cycles | render instructions | flash bytes | static RAM bytes |\n\
         |---|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for run in examples {
        text += &format!(
            "| {} | {} | {} | {}x{} | {} | {:.2} s | {} | {} | {} | {} | {} |\n",
            run.example,
            run.chip,
            run.core,
            run.width,
            run.height,
            thousands(run.cycles),
            run.cycles as f64 / 125e6,
            thousands(run.setup_cycles),
            thousands(run.cycles.saturating_sub(run.setup_cycles)),
            thousands(run.instructions.saturating_sub(run.setup_instructions)),
            thousands(run.flash_bytes),
            thousands(run.static_ram_bytes)
        );
    }
    text
}

/// A part of the report to run instead of all of it (`cargo xtask firmware-report --scene snooker
/// --board mps2-an386 --number f32`): each field left `None` keeps every value. A partial report
/// is written under `firmware/target/report/partial/`, never into docs/firmware-report.md or
/// `docs/firmware-report.json`, whose tables it would cut short.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ReportFilter {
    /// A scene's stem (`snooker`, `lattice`).
    pub scene: Option<String>,
    pub board: Option<Board>,
    pub number: Option<String>,
    /// `scene` or `none`.
    pub optimizations: Option<String>,
    pub primitives: Option<Primitives>,
}

impl ReportFilter {
    pub fn is_everything(&self) -> bool {
        *self == Self::default()
    }

    fn keeps(&self, scene: &str, board: Board, number: &str, primitives: Primitives, optimizations: &str) -> bool {
        let stem = stem(scene);
        self.scene.as_deref().is_none_or(|wanted| wanted == stem)
            && self.board.is_none_or(|wanted| wanted == board)
            && self.number.as_deref().is_none_or(|wanted| wanted == number)
            && self.primitives.is_none_or(|wanted| wanted == primitives)
            && self.optimizations.as_deref().is_none_or(|wanted| wanted == optimizations)
    }

    /// Says what is wrong with a filter that names no scene, number or optimization the report
    /// has, or keeps no run at all.
    fn check(&self) -> Result<(), String> {
        if let Some(scene) = &self.scene {
            if !SCENES.iter().chain(CHAPTER_FIVE_SCENES.iter()).any(|file| stem(file) == scene) {
                return Err(format!("--scene {scene}: the report runs snooker, lattice, snooker-polished, lattice-antialiased, torus, die, lens, cup and nut"));
            }
        }
        if let Some(board) = self.board {
            if !Board::REPORTED.contains(&board) {
                return Err(format!(
                    "--board {}: the report runs on {} (the lm3s811evb's 8 KB hold snooker only: tests/tests/firmware_qemu.rs measures it)",
                    board.name(),
                    Board::REPORTED.map(Board::name).join(", ")
                ));
            }
        }
        if let Some(number) = &self.number {
            if !NUMBERS.contains(&number.as_str()) {
                return Err(format!("--number {number}: one of {}", NUMBERS.join(", ")));
            }
        }
        if let Some(optimizations) = &self.optimizations {
            if !["scene", "none"].contains(&optimizations.as_str()) {
                return Err(format!("--opt {optimizations}: the report runs `scene` and `none`"));
            }
        }
        if plan(self).is_empty() {
            return Err("the filter keeps no run (all-primitives builds are f32 with the scene's optimizations only)".into());
        }
        Ok(())
    }
}

/// What to run: every scene x board x number with the scene's primitives (with the scene's
/// optimizations and with none), then every scene x board with all five primitives; only the
/// runs `filter` keeps.
fn plan(filter: &ReportFilter) -> Vec<(PathBuf, Board, &'static str, Primitives, &'static str)> {
    let root = crate::repository_root();
    let mut plan = Vec::new();
    for optimizations in ["scene", "none"] {
        for scene in SCENES {
            for board in Board::REPORTED {
                for number in NUMBERS {
                    if filter.keeps(scene, board, number, Primitives::Scene, optimizations) {
                        plan.push((root.join(scene), board, number, Primitives::Scene, optimizations));
                    }
                }
            }
        }
    }
    for scene in SCENES {
        for board in Board::REPORTED {
            if filter.keeps(scene, board, ALL_PRIMITIVES_NUMBER, Primitives::All, "scene") {
                plan.push((root.join(scene), board, ALL_PRIMITIVES_NUMBER, Primitives::All, "scene"));
            }
        }
    }
    for scene in CHAPTER_FIVE_SCENES {
        for board in Board::REPORTED {
            for number in CHAPTER_FIVE_NUMBERS {
                if filter.keeps(scene, board, number, Primitives::Scene, "scene") {
                    plan.push((root.join(scene), board, number, Primitives::Scene, "scene"));
                }
            }
        }
    }
    plan
}

/// Runs everything `filter` keeps (printing progress), then writes docs/firmware-report.md's table and the
/// JSON; for a partial report, both under `firmware/target/report/partial/` instead.
pub fn run(filter: &ReportFilter) -> Result<Vec<ReportRun>, String> {
    filter.check()?;
    let plan = plan(filter);
    let mut runs = Vec::with_capacity(plan.len());
    let mut misses = Vec::new();
    let started = std::time::Instant::now();
    for (index, (scene, board, number, primitives, optimizations)) in plan.iter().enumerate() {
        let stem = scene.file_stem().map(|stem| stem.to_string_lossy().into_owned()).unwrap_or_default();
        let label = format!("{stem} {} {number} primitives={} opt={optimizations}", board.name(), primitives.name());
        println!("[{}/{}] {label} ...", index + 1, plan.len());
        let out = crate::firmware_dir()
            .join("target/report")
            .join(format!("{}-{stem}-{number}-{}-{optimizations}", board.name(), primitives.name()));
        let mut options = FirmwareOptions::new(scene, *board, number, out);
        options.primitives = *primitives;
        options.optimizations = (*optimizations).to_owned();
        // Every optimization off runs for minutes under QEMU on the lattice in f64.
        options.timeout = std::time::Duration::from_secs(1200);
        let result = match firmware::run(&options) {
            Ok(result) => result,
            Err(error) => match does_not_fit(&error) {
                Some(reason) => {
                    println!("    does not fit: {reason}");
                    misses.push(ReportMiss { scene: stem, board: *board, number: (*number).to_owned(), primitives: *primitives, optimizations, reason });
                    continue;
                }
                None => return Err(format!("{label}: {error}")),
            },
        };
        let differing_pixels = differing_from_host(&result, scene, number, optimizations).map_err(|error| format!("{label}: {error}"))?;
        let get = |key: &str| result.numbers.get(key).copied().ok_or_else(|| format!("{label}: the report lacks `{key}`"));
        let run = ReportRun {
            scene: stem,
            board: *board,
            number: (*number).to_owned(),
            primitives: *primitives,
            optimizations,
            width: get("width")?,
            height: get("height")?,
            instructions: get("instructions")?,
            frame_instructions: get("frame_instructions")?,
            prepare_instructions: get("prepare_instructions")?,
            render_instructions: get("render_instructions")?,
            pixels: get("pixels")?,
            instructions_per_pixel: get("instructions_per_pixel")?,
            flash_bytes: get("flash_bytes")?,
            static_ram_bytes: get("static_ram_bytes")?,
            stack_peak_bytes: get("stack_peak_bytes")?,
            f64_symbols: get("f64_symbols")?,
            panic_symbols: get("panic_symbols")?,
            fmt_symbols: get("fmt_symbols")?,
            rays_traced: get("rays_traced")?,
            secondary_rays: get("secondary_rays")?,
            differing_pixels,
            flash_areas: result.flash_areas.clone(),
        };
        if differing_pixels != 0 {
            println!("    {differing_pixels} pixels differ from the host's render in {number}");
        }
        println!(
            "    {} instructions per pixel (frame {}: prepare {}, render {}), flash {} B, static RAM {} B, peak stack {} B ({:.0} s so far)",
            run.instructions_per_pixel,
            run.frame_instructions,
            run.prepare_instructions,
            run.render_instructions,
            run.flash_bytes,
            run.static_ram_bytes,
            run.stack_peak_bytes,
            started.elapsed().as_secs_f64()
        );
        runs.push(run);
    }

    let root = crate::repository_root();
    if !filter.is_everything() {
        let directory = crate::firmware_dir().join("target/report/partial");
        std::fs::create_dir_all(&directory).map_err(|error| format!("{}: {error}", directory.display()))?;
        for (name, text) in [("firmware-report.json", json_with_examples(&runs, &misses, &[])), ("table.md", markdown(&runs, &misses))] {
            let path = directory.join(name);
            std::fs::write(&path, text).map_err(|error| format!("{}: {error}", path.display()))?;
            println!("wrote {} (a partial report: docs/ is left as it is)", path.display());
        }
        return Ok(runs);
    }
    let examples = example_runs()?;
    let json_path = root.join("docs/firmware-report.json");
    std::fs::write(&json_path, json_with_examples(&runs, &misses, &examples)).map_err(|error| format!("{}: {error}", json_path.display()))?;
    println!("wrote {}", json_path.display());
    let readme_path = root.join("docs/firmware-report.md");
    let readme = std::fs::read_to_string(&readme_path).map_err(|error| format!("{}: {error}", readme_path.display()))?;
    let updated = replace_between_markers(&readme, &(markdown(&runs, &misses) + &examples_markdown(&examples)))?;
    std::fs::write(&readme_path, updated).map_err(|error| format!("{}: {error}", readme_path.display()))?;
    println!("wrote the table into {}", readme_path.display());
    Ok(runs)
}

/// `{"runs":[{...}, ...]}`, one run a line, keys in a fixed order.
pub fn json(runs: &[ReportRun]) -> String {
    let lines: Vec<String> = runs
        .iter()
        .map(|run| {
            format!(
                "{{\"scene\":\"{}\",\"board\":\"{}\",\"number\":\"{}\",\"primitives\":\"{}\",\"optimizations\":\"{}\",\"width\":{},\"height\":{},\
                 \"instructions\":{},\"frame_instructions\":{},\"prepare_instructions\":{},\"render_instructions\":{},\
                 \"pixels\":{},\"instructions_per_pixel\":{},\"flash_bytes\":{},\
                 \"static_ram_bytes\":{},\"stack_peak_bytes\":{},\"f64_symbols\":{},\"panic_symbols\":{},\"fmt_symbols\":{},\
                 \"rays_traced\":{},\"secondary_rays\":{},\"differing_pixels\":{}}}",
                run.scene,
                run.board.name(),
                run.number,
                run.primitives.name(),
                run.optimizations,
                run.width,
                run.height,
                run.instructions,
                run.frame_instructions,
                run.prepare_instructions,
                run.render_instructions,
                run.pixels,
                run.instructions_per_pixel,
                run.flash_bytes,
                run.static_ram_bytes,
                run.stack_peak_bytes,
                run.f64_symbols,
                run.panic_symbols,
                run.fmt_symbols,
                run.rays_traced,
                run.secondary_rays,
                run.differing_pixels
            )
        })
        .collect();
    format!("{{\"runs\":[\n{}\n]}}\n", lines.join(",\n"))
}

/// The text between the markers: the main table, the builds that did not fit, then the number
/// types without optimizations, scene-only against all primitives, and chapter 5.
pub fn markdown(runs: &[ReportRun], misses: &[ReportMiss]) -> String {
    let mut text = String::new();
    text += "Generated by `cargo xtask firmware-report` (the same figures are in\n\
             `docs/firmware-report.json`): each thesis scene rendered at 128x64 by the firmware under QEMU,\n\
             with the scene's own `optimize` and only the primitives it uses, on four cores: the\n\
             microbit's Cortex-M0 (ARMv6-M, the RP2040's instruction set: no FPU, no divide, no 32x32→64\n\
             multiply; 16 KB of RAM), the lm3s6965evb's Cortex-M3 (no FPU), the mps2-an386's Cortex-M4F\n\
             and the mps2-an505's Cortex-M33 (the RP2350's core), both with a single-precision FPU, so\n\
             `f32` runs in hardware there and in software on the M0 and M3; `f64` is software on all four.\n\
             **Instructions are not cycles**: QEMU counts executed instructions (a TCG plugin, between\n\
             markers in the firmware), so a divide, a load or a taken branch each count as one, and flash\n\
             wait states are not modelled. The count is the frame's, from before the scene is prepared to\n\
             the end of the render (`frame`, and per pixel), split at a marker between the two into\n\
             `prepare` (the scene's preparation in place, the sink's set-up) and `render`. Flash is text +\n\
             data; static RAM is data + bss (the prepared scene with its acceleration structures; no\n\
             framebuffer and no display copy: each row goes to the host and the OLED as it is done).\n\
             `f64 routines` and `panic symbols` count the linked functions of each kind (double-precision\n\
             soft float and libm's `f64` functions; panic paths), from the ELF's symbols; each run's\n\
             `linked-audit.txt` names them. `host` is the picture against the host's render of the same\n\
             scene in the same number type: `=` byte for byte, or the pixels that differ.\n\n";
    text += &format!(
        "Budget on the lm3s6965evb (64 KB RAM, 256 KB flash) for both scenes in `f32`, asserted by\n\
         `tests/tests/firmware_qemu.rs`: flash at most {} KB, static RAM at most {} KB, peak stack at most\n\
         {} KB, so at least {} KB of the RAM stays free, and no initialised statics (`.data`), whose\n\
         values would take flash too (see [firmware/README.md](../firmware/README.md#memory-budget)).\n\n",
        budget::FLASH_BYTES / 1024,
        budget::STATIC_RAM_BYTES / 1024,
        budget::STACK_BYTES / 1024,
        budget::FREE_RAM_BYTES / 1024
    );
    text += "| scene | board | number | instructions per pixel | frame instructions | prepare instructions | render instructions | flash bytes | static RAM bytes | peak stack bytes | f64 routines | panic symbols | host |\n";
    text += "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    let chapter_five = |run: &ReportRun| CHAPTER_FIVE_SCENES.iter().any(|file| stem(file) == run.scene);
    let scene_optimizations = |run: &&ReportRun| run.primitives == Primitives::Scene && run.optimizations == "scene" && !chapter_five(run);
    for run in runs.iter().filter(scene_optimizations) {
        text += &format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            run.scene,
            run.board.name(),
            run.number,
            thousands(run.instructions_per_pixel),
            thousands(run.frame_instructions),
            thousands(run.prepare_instructions),
            thousands(run.render_instructions),
            thousands(run.flash_bytes),
            thousands(run.static_ram_bytes),
            thousands(run.stack_peak_bytes),
            run.f64_symbols,
            run.panic_symbols,
            host_column(run)
        );
    }
    if !misses.is_empty() {
        text += "\nBuilds the board's RAM cannot hold (the build's RAM check, firmware/src/ram.rs: the prepared\n\
                 scene and the stack it reserves; `--stack-reserve` trades the reserve for the risk of an\n\
                 overflow, which the firmware then reports):\n\n\
                 | scene | board | number | primitives | optimizations | why |\n|---|---|---|---|---|---|\n";
        for miss in misses {
            text += &format!("| {} | {} | {} | {} | {} | {} |\n", miss.scene, miss.board.name(), miss.number, miss.primitives.name(), miss.optimizations, miss.reason);
        }
    }
    text += &without_optimizations(runs);
    text += &format!(
        "\nOnly the scene's primitives against all five (the thesis's four and the torus), in\n\
         `{ALL_PRIMITIVES_NUMBER}` (snooker uses only spheres, the lattice spheres and cylinders):\n\n"
    );
    text += "| scene | board | flash, scene's primitives | flash, all five | flash difference | static RAM, scene's primitives | static RAM, all five |\n";
    text += "|---|---|---:|---:|---:|---:|---:|\n";
    for all in runs.iter().filter(|run| run.primitives == Primitives::All) {
        let Some(own) = runs.iter().find(|run| {
            scene_optimizations(run) && run.scene == all.scene && run.board == all.board && run.number == all.number
        }) else {
            continue;
        };
        text += &format!(
            "| {} | {} | {} | {} | {} | {} | {} |\n",
            all.scene,
            all.board.name(),
            thousands(own.flash_bytes),
            thousands(all.flash_bytes),
            signed_thousands(all.flash_bytes as i64 - own.flash_bytes as i64),
            thousands(own.static_ram_bytes),
            thousands(all.static_ram_bytes)
        );
    }
    text += &chapter_five_table(runs);
    text += &flash_table(runs);
    text
}

/// Where the flash goes: the thesis scenes on the Cortex-M3 (lm3s6965evb), with their own
/// `optimize` and primitives, in `f32`, `fixed` and `soft32`, by area (`elf::area`: the core's
/// and the firmware's modules, other crates whole); areas under 1 % of every build summed.
fn flash_table(runs: &[ReportRun]) -> String {
    let columns: Vec<&ReportRun> = SCENES
        .iter()
        .flat_map(|file| ["f32", "fixed", "soft32"].map(move |number| (stem(file), number)))
        .filter_map(|(scene, number)| {
            runs.iter().find(|run| {
                run.scene == scene && run.number == number && run.board == Board::Lm3s6965evb && run.primitives == Primitives::Scene && run.optimizations == "scene"
            })
        })
        .collect();
    if columns.is_empty() {
        return String::new();
    }
    let bytes = |run: &ReportRun, area: &str| run.flash_areas.iter().find(|(name, _)| name == area).map_or(0, |(_, bytes)| *bytes);
    let mut areas: Vec<String> = Vec::new();
    for run in &columns {
        for (area, _) in &run.flash_areas {
            if !areas.contains(area) && columns.iter().any(|run| bytes(run, area) * 100 >= run.flash_bytes) {
                areas.push(area.clone());
            }
        }
    }
    areas.sort_by_key(|area| std::cmp::Reverse(columns.iter().map(|run| bytes(run, area)).max().unwrap_or(0)));
    let mut text = String::from(
        "\nWhere the flash goes on the Cortex-M3 (lm3s6965evb), each thesis scene with its own `optimize`: bytes by\n\
         area (`xtask::elf::area`: the core's and the firmware's modules, other crates whole; `(other)`:\n\
         symbols without a Rust path: the compiler's runtime routines by their C names, cortex-m-rt's\n\
         `Reset` and vector table; `(no symbol)`: bytes no symbol covers, alignment and unnamed\n\
         constants). Each run's `flash-by-function.txt` lists every symbol, largest first.\n\n| area |",
    );
    for run in &columns {
        text += &format!(" {} {} |", run.scene, run.number);
    }
    text += "\n|---|";
    text += &"---:|".repeat(columns.len());
    text += "\n";
    for area in &areas {
        text += &format!("| `{area}` |");
        for run in &columns {
            text += &format!(" {} |", thousands(bytes(run, area)));
        }
        text += "\n";
    }
    text += "| the rest |";
    for run in &columns {
        let listed: u64 = areas.iter().map(|area| bytes(run, area)).sum();
        text += &format!(" {} |", thousands(run.flash_bytes.saturating_sub(listed)));
    }
    text += "\n| **flash** |";
    for run in &columns {
        text += &format!(" **{}** |", thousands(run.flash_bytes));
    }
    text + "\n"
}

/// `=` when the run's picture is the host's byte for byte, else how many pixels differ.
fn host_column(run: &ReportRun) -> String {
    if run.differing_pixels == 0 {
        "=".to_owned()
    } else {
        format!("{} differ", thousands(run.differing_pixels))
    }
}

/// The chapter-5 scenes: the ray tree (`snooker-polished`) and antialiasing
/// (`lattice-antialiased`), with their rays per pixel and the tree's secondary rays.
fn chapter_five_table(runs: &[ReportRun]) -> String {
    let chapter_five: Vec<&ReportRun> = runs
        .iter()
        .filter(|run| CHAPTER_FIVE_SCENES.iter().any(|file| stem(file) == run.scene))
        .collect();
    if chapter_five.is_empty() {
        return String::new();
    }
    let mut text = String::from(
        "\nThe thesis's chapter 5 on the chip (docs/features.md, \"Chapter 5\"): `snooker-polished` (the ray tree:\n\
         reflective balls, a glass cue ball, two lights, depth 4) and `lattice-antialiased` (corners\n\
         split twice where they differ by 6 %); and the ring torus it proposes (§5.2.1), `torus` (two\n\
         tori, a ball and a table, shadows on); and the solids of chapter 3 (docs/features.md, \"Solids\"): `die` (a\n\
         cube ∩ a sphere minus six pips), `lens` (glass: sphere ∩ sphere), `cup` (a torus handle) and\n\
         `nut` (a hexagonal prism minus a cylinder). With the scene's own `optimize`; rays per pixel counts\n\
         every primary ray (with antialiasing, every corner and sub-corner), secondary rays the tree's:\n\n\
         | scene | board | number | instructions per pixel | frame instructions | rays per pixel | secondary rays | flash bytes | static RAM bytes | peak stack bytes | f64 routines | panic symbols | host |\n\
         |---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    for run in chapter_five {
        text += &format!(
            "| {} | {} | {} | {} | {} | {:.2} | {} | {} | {} | {} | {} | {} | {} |\n",
            run.scene,
            run.board.name(),
            run.number,
            thousands(run.instructions_per_pixel),
            thousands(run.frame_instructions),
            run.rays_traced as f64 / run.pixels.max(1) as f64,
            thousands(run.secondary_rays),
            thousands(run.flash_bytes),
            thousands(run.static_ram_bytes),
            thousands(run.stack_peak_bytes),
            run.f64_symbols,
            run.panic_symbols,
            host_column(run)
        );
    }
    text
}

/// The table of instructions per pixel with every optimization off, against `f32` on the same
/// board: the number type's own cost, which the optimizations' per-render work (in `f64`, the
/// same for every number type) dilutes in the main table.
fn without_optimizations(runs: &[ReportRun]) -> String {
    let none = |run: &&ReportRun| run.primitives == Primitives::Scene && run.optimizations == "none";
    if !runs.iter().any(|run| none(&run)) {
        return String::new();
    }
    let mut text = String::from(
        "\nWith every optimization off (`--opt none`), where the intersection and shading arithmetic\n\
         dominates, instructions per pixel and, in brackets, how many times fewer than `f32` on the same\n\
         board. With the optimizations on, far fewer intersections are left, and work that is the same\n\
         for every number type (the scene's preparation and the optimizations' projections, done in\n\
         `f64`; writing pixels and the OLED) dilutes the differences in the table above:\n\n",
    );
    text += &format!("| scene | board | {} |\n|---|---|{}\n", NUMBERS.join(" | "), "---:|".repeat(NUMBERS.len()));
    for scene in SCENES {
        let stem = stem(scene);
        for board in Board::REPORTED {
            let find = |number: &str| runs.iter().filter(none).find(|run| run.scene == stem && run.board == board && run.number == number);
            let Some(f32_run) = find("f32") else { continue };
            text += &format!("| {stem} | {} |", board.name());
            for number in NUMBERS {
                text += &match find(number) {
                    Some(run) => format!(
                        " {} ({:.2}x) |",
                        thousands(run.instructions_per_pixel),
                        f32_run.instructions_per_pixel as f64 / run.instructions_per_pixel.max(1) as f64
                    ),
                    None => " — |".to_owned(),
                };
            }
            text += "\n";
        }
    }
    text
}

/// The report's page (docs/firmware-report.md) with `table` between the markers; the markers
/// (in a section of their own) are appended when absent.
pub fn replace_between_markers(readme: &str, table: &str) -> Result<String, String> {
    match (readme.find(START_MARKER), readme.find(END_MARKER)) {
        (Some(start), Some(end)) if start < end => {
            let before = &readme[..start + START_MARKER.len()];
            let after = &readme[end..];
            Ok(format!("{before}\n{table}{after}"))
        }
        (None, None) => {
            let separator = if readme.ends_with('\n') { "\n" } else { "\n\n" };
            Ok(format!("{readme}{separator}{SECTION_HEADING}\n\n{START_MARKER}\n{table}{END_MARKER}\n"))
        }
        _ => Err(format!("docs/firmware-report.md: `{START_MARKER}` must come once, before `{END_MARKER}`")),
    }
}

/// 1234567 -> "1,234,567".
pub fn thousands(value: u64) -> String {
    let digits = value.to_string();
    let mut out = String::new();
    for (index, digit) in digits.chars().enumerate() {
        if index > 0 && (digits.len() - index).is_multiple_of(3) {
            out.push(',');
        }
        out.push(digit);
    }
    out
}

/// -1234 -> "-1,234", 1234 -> "+1,234".
fn signed_thousands(value: i64) -> String {
    let sign = if value < 0 { "-" } else { "+" };
    format!("{sign}{}", thousands(value.unsigned_abs()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thousands_groups_digits() {
        assert_eq!(thousands(0), "0");
        assert_eq!(thousands(999), "999");
        assert_eq!(thousands(1000), "1,000");
        assert_eq!(thousands(1234567), "1,234,567");
        assert_eq!(signed_thousands(-1234), "-1,234");
        assert_eq!(signed_thousands(2156), "+2,156");
    }

    #[test]
    fn the_examples_follow_the_runs_in_the_json_and_get_their_own_table() {
        let example = ExampleRun {
            example: "pico-ssd1306",
            chip: "RP2040",
            core: "Cortex-M0+",
            width: 128,
            height: 64,
            cycles: 69_983_684,
            setup_cycles: 10_272_351,
            instructions: 50_000_000,
            setup_instructions: 8_000_000,
            flash_bytes: 100_836,
            static_ram_bytes: 9_000,
        };
        let miss = ReportMiss {
            scene: "lattice".into(),
            board: Board::Microbit,
            number: "f64".into(),
            primitives: Primitives::Scene,
            optimizations: "scene",
            reason: "needs 24,552 bytes of RAM (the prepared scene 15,280 for 54 objects in f64, \"x\"), the microbit has 16,384".into(),
        };
        let text = json_with_examples(&[], std::slice::from_ref(&miss), std::slice::from_ref(&example));
        assert_eq!(
            text,
            "{\"runs\":[\n\n],\n\"did_not_fit\":[\n{\"scene\":\"lattice\",\"board\":\"microbit\",\"number\":\"f64\",\"primitives\":\"scene\",\"optimizations\":\"scene\",\
             \"reason\":\"needs 24,552 bytes of RAM (the prepared scene 15,280 for 54 objects in f64, \\\"x\\\"), the microbit has 16,384\"}\n],\n\"examples\":[\n{\"example\":\"pico-ssd1306\",\"chip\":\"RP2040\",\"core\":\"Cortex-M0+\",\"scene\":\"snooker\",\"number\":\"f32\",\"width\":128,\"height\":64,\"cycles\":69983684,\"setup_cycles\":10272351,\"instructions\":50000000,\"setup_instructions\":8000000,\"flash_bytes\":100836,\"static_ram_bytes\":9000}\n]}\n"
        );
        let table = examples_markdown(&[example]);
        assert!(table.contains("| pico-ssd1306 | RP2040 | Cortex-M0+ | 128x64 | 69,983,684 | 0.56 s | 10,272,351 | 59,711,333 | 42,000,000 | 100,836 | 9,000 |\n"), "{table}");
        assert_eq!(examples_markdown(&[]), "");
    }

    #[test]
    fn a_build_that_fails_the_ram_check_does_not_fit() {
        let error = "building the firmware failed: /r/scenes/lattice.mts: needs 19,548 bytes of RAM (the prepared scene 10,592 for 54 objects in f32, framebuffer 0 for 128x64, stack reserve 8,956), the microbit has 16,384 (firmware/README.md, \"When it fails\")\nerror[E0080]: ...";
        assert_eq!(
            does_not_fit(error).as_deref(),
            Some("needs 19,548 bytes of RAM (the prepared scene 10,592 for 54 objects in f32, framebuffer 0 for 128x64, stack reserve 8,956), the microbit has 16,384")
        );
        assert_eq!(does_not_fit("building the firmware failed: error[E0433]: cannot find `x`"), None);
    }

    #[test]
    fn the_table_replaces_only_what_is_between_the_markers() {
        let readme = format!("intro\n{START_MARKER}\nold table\n{END_MARKER}\nrest\n");
        let updated = replace_between_markers(&readme, "new table\n").unwrap();
        assert_eq!(updated, format!("intro\n{START_MARKER}\nnew table\n{END_MARKER}\nrest\n"));
    }

    #[test]
    fn markers_are_added_in_their_section_when_absent() {
        let updated = replace_between_markers("intro\n", "table\n").unwrap();
        assert_eq!(updated, format!("intro\n\n{SECTION_HEADING}\n\n{START_MARKER}\ntable\n{END_MARKER}\n"));
    }

    #[test]
    fn a_filter_keeps_only_its_runs() {
        let boards = Board::REPORTED.len();
        assert_eq!(plan(&ReportFilter::default()).len(), 2 * 2 * NUMBERS.len() * boards + 2 * boards + CHAPTER_FIVE_SCENES.len() * boards * CHAPTER_FIVE_NUMBERS.len());
        let one = ReportFilter { scene: Some("snooker".into()), board: Some(Board::Mps2An386), number: Some("f32".into()), ..Default::default() };
        let kept: Vec<(Primitives, &str)> = plan(&one).into_iter().map(|(_, _, _, primitives, optimizations)| (primitives, optimizations)).collect();
        assert_eq!(kept, [(Primitives::Scene, "scene"), (Primitives::Scene, "none"), (Primitives::All, "scene")]);
        assert!(plan(&one).iter().all(|(scene, board, number, _, _)| scene.ends_with("scenes/snooker.mts") && *board == Board::Mps2An386 && *number == "f32"));
        let none = ReportFilter { number: Some("fixed".into()), primitives: Some(Primitives::All), ..Default::default() };
        assert!(none.check().unwrap_err().contains("keeps no run"));
        assert!(ReportFilter { scene: Some("teapot".into()), ..Default::default() }.check().is_err());
        // A scene in a folder is named by its file's stem.
        let die = ReportFilter { scene: Some("die".into()), ..Default::default() };
        assert_eq!(plan(&die).len(), boards * CHAPTER_FIVE_NUMBERS.len());
        assert!(plan(&die).iter().all(|(scene, _, _, _, _)| scene.ends_with("scenes/csg/die.mts")));
    }

    #[test]
    fn the_table_has_the_frame_its_parts_and_the_audit() {
        let run = ReportRun {
            scene: "snooker".into(),
            board: Board::Mps2An386,
            number: "f32".into(),
            primitives: Primitives::Scene,
            optimizations: "scene",
            width: 128,
            height: 64,
            instructions: 35_882_729,
            frame_instructions: 35_882_729,
            prepare_instructions: 22_777_349,
            render_instructions: 13_105_380,
            pixels: 8192,
            instructions_per_pixel: 4380,
            flash_bytes: 61_956,
            static_ram_bytes: 18_080,
            stack_peak_bytes: 9360,
            f64_symbols: 30,
            panic_symbols: 5,
            fmt_symbols: 2,
            rays_traced: 3000,
            secondary_rays: 0,
            differing_pixels: 0,
            flash_areas: Vec::new(),
        };
        let mut differing = run.clone();
        differing.board = Board::Microbit;
        differing.differing_pixels = 1234;
        let table = markdown(&[run, differing], &[]);
        assert!(table.contains("| instructions per pixel | frame instructions | prepare instructions | render instructions |"), "{table}");
        assert!(table.contains("| f64 routines | panic symbols | host |\n"), "{table}");
        assert!(table.contains("| snooker | microbit | f32 | 4,380 | 35,882,729 | 22,777,349 | 13,105,380 | 61,956 | 18,080 | 9,360 | 30 | 5 | 1,234 differ |\n"), "{table}");
        assert!(
            table.contains("| snooker | mps2-an386 | f32 | 4,380 | 35,882,729 | 22,777,349 | 13,105,380 | 61,956 | 18,080 | 9,360 | 30 | 5 | = |\n"),
            "{table}"
        );
    }

    #[test]
    fn the_json_has_the_shape_bench_reads() {
        let run = ReportRun {
            scene: "snooker".into(),
            board: Board::Lm3s6965evb,
            number: "f32".into(),
            primitives: Primitives::Scene,
            optimizations: "scene",
            width: 128,
            height: 64,
            instructions: 8192,
            frame_instructions: 8192,
            prepare_instructions: 192,
            render_instructions: 8000,
            pixels: 8192,
            instructions_per_pixel: 1,
            flash_bytes: 2,
            static_ram_bytes: 3,
            stack_peak_bytes: 4,
            f64_symbols: 5,
            panic_symbols: 6,
            fmt_symbols: 7,
            rays_traced: 8,
            secondary_rays: 9,
            differing_pixels: 0,
            flash_areas: Vec::new(),
        };
        assert_eq!(
            json(&[run]),
            "{\"runs\":[\n{\"scene\":\"snooker\",\"board\":\"lm3s6965evb\",\"number\":\"f32\",\"primitives\":\"scene\",\
             \"optimizations\":\"scene\",\"width\":128,\"height\":64,\"instructions\":8192,\"frame_instructions\":8192,\
             \"prepare_instructions\":192,\"render_instructions\":8000,\"pixels\":8192,\"instructions_per_pixel\":1,\
             \"flash_bytes\":2,\"static_ram_bytes\":3,\"stack_peak_bytes\":4,\"f64_symbols\":5,\"panic_symbols\":6,\"fmt_symbols\":7,\
             \"rays_traced\":8,\"secondary_rays\":9,\"differing_pixels\":0}\n]}\n"
        );
    }
}
