//! `cargo xtask firmware`: build the firmware for one scene, board and number type, run it
//! under QEMU, and leave `framebuffer.bin`, `oled.png` (lm3s6965evb), `report.json` and
//! `linked-audit.txt` in the output directory.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::Mutex;
use std::time::Duration;

use microtrace::model::Primitive;
use microtrace::number::NumberKind;

use crate::elf;
use crate::oled;
use crate::qemu::{self, Machine, Monitor, QemuRun};
use crate::setup;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Board {
    Lm3s6965evb,
    Mps2An386,
    /// The BBC micro:bit: a Cortex-M0 (ARMv6-M, the RP2040's instruction set), 16 KB of RAM.
    Microbit,
    /// A Cortex-M33 with an FPU (ARMv8-M Mainline, the RP2350's core).
    Mps2An505,
    /// The smallest: a Cortex-M3 with 64 KB of flash and 8 KB of RAM.
    Lm3s811evb,
    /// A Cortex-M4F on an STM32F405 (Netduino Plus 2): the board added by the checklist.
    Netduinoplus2,
}

/// The board table (firmware/boards.rs), shared with the firmware's build script.
#[path = "../../firmware/boards.rs"]
mod boards;
pub use boards::{BoardDisplay, BoardFacts, BOARDS};

impl Board {
    pub const ALL: [Board; 6] = [Board::Lm3s6965evb, Board::Mps2An386, Board::Microbit, Board::Mps2An505, Board::Lm3s811evb, Board::Netduinoplus2];
    /// The boards the firmware report runs every scene on: each core once, with the same
    /// budget of 256 KB of code and 64 KB (16 KB on the micro:bit) of RAM. The lm3s811evb's
    /// 8 KB hold snooker, not every scene: its own test measures it.
    pub const REPORTED: [Board; 4] = [Board::Lm3s6965evb, Board::Mps2An386, Board::Microbit, Board::Mps2An505];

    /// Its facts: its row of the board table, in `ALL`'s order (a test checks the names).
    pub fn facts(self) -> &'static BoardFacts {
        let row = match self {
            Board::Lm3s6965evb => 0,
            Board::Mps2An386 => 1,
            Board::Microbit => 2,
            Board::Mps2An505 => 3,
            Board::Lm3s811evb => 4,
            Board::Netduinoplus2 => 5,
        };
        &BOARDS[row]
    }

    /// The name on the command line, and the firmware's cargo feature.
    pub fn name(self) -> &'static str {
        self.facts().name
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|board| board.name() == name)
    }

    pub fn rust_target(self) -> &'static str {
        self.facts().rust_target
    }

    fn machine(self) -> Machine {
        Machine { name: self.facts().qemu_machine, cpu: self.facts().qemu_cpu }
    }

    /// Whether a render of `size` is shown on the board's display (and so captured): the
    /// lm3s6965evb's 128x64 OLED shows any; the lm3s811evb drives its 96x16 one only for a
    /// render of that size (firmware/src/board/lm3s811evb/mod.rs).
    pub fn shows(self, size: (u16, u16)) -> bool {
        match self.facts().display {
            BoardDisplay::AnySize => true,
            BoardDisplay::Exactly(width, height) => size == (width, height),
            BoardDisplay::None => false,
        }
    }
}

#[cfg(test)]
mod board_table_tests {
    use super::{Board, BOARDS};

    /// Every board has its own row, in order, and every row a board.
    #[test]
    fn each_board_is_its_row_of_the_table() {
        assert_eq!(Board::ALL.len(), BOARDS.len());
        for (board, row) in Board::ALL.into_iter().zip(BOARDS.iter()) {
            assert_eq!(board.facts(), row);
        }
        let names: std::collections::BTreeSet<&str> = BOARDS.iter().map(|row| row.name).collect();
        assert_eq!(names.len(), BOARDS.len(), "two rows with one name");
    }
}

/// Which primitives' intersection code the firmware links.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitives {
    /// Only those the scene uses (the default).
    Scene,
    /// All four, whatever the scene uses (for comparing footprints).
    All,
}

impl Primitives {
    /// The name in reports: `scene` or `all`.
    pub fn name(self) -> &'static str {
        match self {
            Primitives::Scene => "scene",
            Primitives::All => "all",
        }
    }
}

/// What the fault test provokes (`cargo xtask firmware --provoke`; firmware/src/fault.rs): the
/// firmware is built with `MICROTRACE_FAULT_TEST=1` and does it before preparing the scene, when
/// it finds the file `provoke-NAME` in QEMU's directory. One build serves them all.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fault {
    /// `panic!` with a message.
    Panic,
    /// A write to an address outside the flash, RAM and peripherals, which the MPU stops.
    HardFault,
    /// PendSV pended: an exception no handler expects (cortex-m-rt's default would spin).
    UnexpectedInterrupt,
    /// Recursion until the stack runs off the bottom of RAM.
    StackOverflow,
}

impl Fault {
    pub const ALL: [Fault; 4] = [Fault::Panic, Fault::HardFault, Fault::UnexpectedInterrupt, Fault::StackOverflow];

    /// The name on the command line and in the file `provoke-NAME`.
    pub fn name(self) -> &'static str {
        match self {
            Fault::Panic => "panic",
            Fault::HardFault => "hard-fault",
            Fault::UnexpectedInterrupt => "unexpected-interrupt",
            Fault::StackOverflow => "stack-overflow",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|fault| fault.name() == name)
    }
}

#[derive(Clone, Debug)]
pub struct FirmwareOptions {
    pub scene: PathBuf,
    /// `f64`, `f32`, `fixed`, `fixed16`, `f32-micromath` or `soft32` (firmware/build.rs maps them to types).
    pub number: String,
    pub board: Board,
    /// `scene` (keep the scene's `optimize`), `all`, `none`, or a comma list.
    pub optimizations: String,
    pub primitives: Primitives,
    /// Build with the firmware's `progressive` feature: the render traces coarse to fine.
    pub progressive: bool,
    /// Build with the firmware's `framebuffer` feature: the framebuffer render instead of the
    /// streamed one (the same picture and statistics; 8 KB more static RAM).
    pub framebuffer: bool,
    pub out: PathBuf,
    pub timeout: Duration,
    /// Build the fault test and provoke this fault (the run then fails, saying what happened).
    pub provoke: Option<Fault>,
    /// The stack the build's RAM check keeps free (`MICROTRACE_STACK_RESERVE`; firmware/src/ram.rs),
    /// when not its default of 12 KB.
    pub stack_reserve: Option<u32>,
    /// The render's size (`MICROTRACE_SIZE`): [`FIRMWARE_SIZE`] unless a display of another
    /// size is the target (the lm3s811evb's 96x16 OLED).
    pub size: (u16, u16),
}

impl FirmwareOptions {
    pub fn new(scene: impl Into<PathBuf>, board: Board, number: &str, out: impl Into<PathBuf>) -> Self {
        Self {
            scene: scene.into(),
            number: number.to_owned(),
            board,
            optimizations: "scene".to_owned(),
            primitives: Primitives::Scene,
            progressive: false,
            framebuffer: false,
            out: out.into(),
            timeout: Duration::from_secs(300),
            provoke: None,
            stack_reserve: None,
            size: FIRMWARE_SIZE,
        }
    }
}

/// What one run left in the output directory.
#[derive(Clone, Debug)]
pub struct FirmwareRun {
    pub elf: PathBuf,
    pub framebuffer: PathBuf,
    pub oled_png: Option<PathBuf>,
    pub report_json: PathBuf,
    /// `linked-audit.txt`: the names of the audit's symbols.
    pub linked_audit_txt: PathBuf,
    /// The f64, panic and formatting symbols the ELF links (their counts are in `numbers`).
    pub audit: elf::LinkedAudit,
    /// Where the flash goes: each area's bytes, largest first (`flash-by-function.txt` beside
    /// the ELF lists every symbol).
    pub flash_areas: Vec<(String, u64)>,
    /// Every integer of the report, by key (`frame_instructions`, `instructions` (the same),
    /// `prepare_instructions`, `render_instructions`, `pixels`, `flash_bytes`, ...).
    pub numbers: BTreeMap<String, u64>,
}

/// Firmware builds share one cargo target directory: a build and the copy of its ELF happen
/// under this lock so that concurrent runs (the tests) never run each other's firmware.
static BUILD_LOCK: Mutex<()> = Mutex::new(());

/// The objects a scene may have at build time: what `microtrace::bake` bakes at most.
pub const FIRMWARE_SCENE_CAPACITY: usize = microtrace::bake::BAKE_CAPACITY;

/// The firmware's render size (`MICROTRACE_SIZE`): the OLED's.
pub const FIRMWARE_SIZE: (u16, u16) = (128, 64);

pub use boards::LM3S811EVB_OLED;

/// The number types firmware/build.rs knows.
pub const NUMBERS: [&str; NumberKind::ALL.len()] = {
    let mut names = [""; NumberKind::ALL.len()];
    let mut index = 0;
    while index < names.len() {
        names[index] = NumberKind::ALL[index].name();
        index += 1;
    }
    names
};

pub fn run(options: &FirmwareOptions) -> Result<FirmwareRun, String> {
    check_options(options)?;
    let scene = options
        .scene
        .canonicalize()
        .map_err(|error| format!("scene {}: {error}", options.scene.display()))?;
    let features = match options.primitives {
        Primitives::Scene => primitive_features(&scene)?,
        Primitives::All => Primitive::ALL.into_iter().map(Primitive::name).collect(),
    };
    setup::ensure_tools(options.board.rust_target())?;

    std::fs::create_dir_all(&options.out).map_err(|error| format!("{}: {error}", options.out.display()))?;
    let out = options.out.canonicalize().map_err(|error| format!("{}: {error}", options.out.display()))?;
    for stale in ["framebuffer.bin", "report.txt", "report.json", "oled.png", "oled.ppm", "instructions.txt", "linked-audit.txt", "screendump.wanted", "screendump.done"] {
        let _ = std::fs::remove_file(out.join(stale));
    }
    for fault in Fault::ALL {
        let _ = std::fs::remove_file(out.join(format!("provoke-{}", fault.name())));
    }
    if let Some(fault) = options.provoke {
        touch(&out.join(format!("provoke-{}", fault.name())))?;
    }

    let elf_path = out.join("firmware.elf");
    {
        let _guard = BUILD_LOCK.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        let built = build(options, &scene, &features)?;
        std::fs::copy(&built, &elf_path).map_err(|error| format!("copying {}: {error}", built.display()))?;
    }
    let elf_bytes = std::fs::read(&elf_path).map_err(|error| format!("{}: {error}", elf_path.display()))?;
    let footprint = elf::footprint(&elf_bytes)?;
    let audit = elf::audit(&elf_bytes)?;
    let linked_audit_txt = out.join("linked-audit.txt");
    std::fs::write(&linked_audit_txt, audit.text()).map_err(|error| format!("{}: {error}", linked_audit_txt.display()))?;
    let (flash_symbols, flash_areas) = elf::flash_symbols(&elf_bytes)?;
    let flash_txt = out.join("flash-by-function.txt");
    std::fs::write(&flash_txt, elf::flash_text(&flash_symbols, &flash_areas)).map_err(|error| format!("{}: {error}", flash_txt.display()))?;
    let start = elf::function_address(&elf_bytes, "microtrace_measure_start")?;
    let render = elf::function_address(&elf_bytes, "microtrace_measure_render")?;
    let end = elf::function_address(&elf_bytes, "microtrace_measure_end")?;

    let plugin = qemu::instruction_count_plugin(&crate::firmware_dir().join("target/qemu-plugin"))?;
    let instructions_path = out.join("instructions.txt");
    let plugin_arguments =
        format!("{},start={start:#x},render={render:#x},end={end:#x},out={}", plugin.display(), instructions_path.display());
    run_qemu(options, &elf_path, &out, &plugin_arguments)?;

    let mut numbers = read_key_values(&out.join("report.txt"))?;
    let instructions = read_key_values(&instructions_path)
        .map_err(|error| format!("no instruction count (did the frame reach its end marker?): {error}"))?;
    numbers.extend(instructions);
    let mut integers: BTreeMap<String, u64> = numbers.iter().filter_map(|(key, value)| Some((key.clone(), value.parse().ok()?))).collect();
    integers.insert("flash_bytes".into(), footprint.flash_bytes());
    integers.insert("static_ram_bytes".into(), footprint.static_ram_bytes());
    integers.insert("text_bytes".into(), footprint.text);
    integers.insert("data_bytes".into(), footprint.data);
    integers.insert("bss_bytes".into(), footprint.bss);
    integers.insert("f64_symbols".into(), audit.f64.len() as u64);
    integers.insert("panic_symbols".into(), audit.panic.len() as u64);
    integers.insert("fmt_symbols".into(), audit.fmt.len() as u64);
    for key in ["frame_instructions", "pixels", "stack_peak_bytes"] {
        if !integers.contains_key(key) {
            return Err(format!("the firmware's report lacks `{key}`"));
        }
    }
    for key in ["prepare_instructions", "render_instructions"] {
        if !integers.contains_key(key) {
            return Err(format!(
                "the instruction count lacks `{key}`: the frame reached its end marker without passing microtrace_measure_render"
            ));
        }
    }
    // `instructions` (and per pixel) are the frame's, as `frame_instructions`: the name older
    // readers know.
    let frame = integers["frame_instructions"];
    let pixels = integers["pixels"].max(1);
    integers.insert("instructions".into(), frame);
    integers.insert("frame_instructions_per_pixel".into(), frame / pixels);
    integers.insert("instructions_per_pixel".into(), frame / pixels);

    let mut names = BTreeMap::new();
    names.insert("board", options.board.name().to_owned());
    names.insert("number", options.number.clone());
    names.insert("scene", scene.file_name().map(|name| name.to_string_lossy().into_owned()).unwrap_or_default());
    names.insert("optimizations", options.optimizations.clone());
    names.insert("primitives", options.primitives.name().to_owned());
    if options.progressive {
        names.insert("display", "progressive".to_owned());
    }
    if options.framebuffer {
        names.insert("render", "framebuffer".to_owned());
    }
    let report_json = out.join("report.json");
    std::fs::write(&report_json, json(&names, &integers)).map_err(|error| format!("{}: {error}", report_json.display()))?;
    let _ = std::fs::remove_file(out.join("report.txt"));
    let _ = std::fs::remove_file(&instructions_path);

    let framebuffer = out.join("framebuffer.bin");
    let oled_png = options.board.shows(options.size).then(|| out.join("oled.png"));
    Ok(FirmwareRun { elf: elf_path, framebuffer, oled_png, report_json, linked_audit_txt, audit, flash_areas, numbers: integers })
}

/// Says what is wrong with `--number` and `--opt` before anything is built.
fn check_options(options: &FirmwareOptions) -> Result<(), String> {
    if !NUMBERS.contains(&options.number.as_str()) {
        return Err(format!("unknown number type `{}` (one of {})", options.number, NUMBERS.join(", ")));
    }
    let optimizations = options.optimizations.as_str();
    if optimizations != "scene" {
        if let Err(name) = microtrace::model::Optimizations::from_list(optimizations) {
            return Err(format!("unknown optimization `{name}` in --opt (scene, all, none, or a list of pixelbuffer,extents,grid,sortlist)"));
        }
    }
    Ok(())
}

/// The `cube`/`sphere`/`cylinder`/`cone`/`torus` features the scene needs (its objects' and its
/// solids' operands'), `csg` when it has solids, `ray-tree` when its
/// objects reflect or transmit and `antialias` when it antialiases (the firmware models only those), parsing it with the same parser as the firmware's build script.
fn primitive_features(scene: &Path) -> Result<Vec<&'static str>, String> {
    let description = parse_any_size(scene)?;
    let mut features: Vec<&'static str> = Primitive::ALL
        .into_iter()
        .filter(|primitive| description.primitives().any(|(used, _)| used.index() == primitive.index()))
        .map(Primitive::name)
        .collect();
    // Solids, when the scene has any (thesis chapter 3).
    if !description.solids.is_empty() {
        features.push("csg");
    }
    // The ray tree, when an object reflects or transmits (chapter 5).
    if description.objects.iter().any(|object| object.material.spawns_rays()) {
        features.push("ray-tree");
    }
    // Antialiasing, when the scene asks for it (chapter 5).
    if description.antialias.is_some() {
        features.push("antialias");
    }
    Ok(features)
}

/// The scene parsed whatever its size (its features, for a build that only sizes a scene of
/// more objects than the build bakes: firmware/build.rs's `size_only`).
fn parse_any_size(scene: &Path) -> Result<microtrace::model::Description<Vec<microtrace::model::ObjectDescription>>, String> {
    let text = std::fs::read(scene).map_err(|error| format!("scene {}: {error}", scene.display()))?;
    microtrace::parser::parse_file(&scene.to_string_lossy(), &text).map_err(|error| {
        if error.line == 0 { format!("{}: {error}", scene.display()) } else { format!("{}:{error}", scene.display()) }
    })
}

/// The objects of the scene as traced (an NFF polygon counts its triangles), whatever its size.
pub fn scene_objects(scene: &Path) -> Result<usize, String> {
    parse_any_size(scene).map(|description| description.objects.len())
}

/// Builds the firmware with the given primitive features instead of the scene's own (for
/// checking that a mismatch fails the build); returns the ELF path or the build's errors.
pub fn build_with_primitives(options: &FirmwareOptions, primitive_features: &[&str]) -> Result<PathBuf, String> {
    check_options(options)?;
    setup::ensure_tools(options.board.rust_target())?;
    let scene = options.scene.canonicalize().map_err(|error| format!("scene {}: {error}", options.scene.display()))?;
    let _guard = BUILD_LOCK.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    build(options, &scene, primitive_features)
}

/// `cargo build --release` of the firmware; returns the ELF.
fn build(options: &FirmwareOptions, scene: &Path, primitive_features: &[&str]) -> Result<PathBuf, String> {
    let firmware = crate::firmware_dir();
    let target_dir = firmware.join("target");
    let mut features = vec![options.board.name()];
    features.extend_from_slice(primitive_features);
    features.extend(NumberKind::from_name(&options.number).and_then(NumberKind::feature));
    if options.progressive {
        features.push("progressive");
    }
    if options.framebuffer {
        features.push("framebuffer");
    }
    let output = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .args(["build", "--release", "--quiet", "--no-default-features"])
        .args(["--features", &features.join(",")])
        .args(["--target", options.board.rust_target()])
        .arg("--target-dir")
        .arg(&target_dir)
        .current_dir(&firmware)
        // The caller's build settings are not the firmware's (its rustflags add link.x).
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("CARGO_BUILD_TARGET")
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env("MICROTRACE_SCENE", scene)
        .env("MICROTRACE_NUMBER", &options.number)
        .env("MICROTRACE_OPT", &options.optimizations)
        .env("MICROTRACE_SIZE", format!("{}x{}", options.size.0, options.size.1))
        .env("MICROTRACE_FAULT_TEST", if options.provoke.is_some() { "1" } else { "0" })
        .env("MICROTRACE_STACK_RESERVE", options.stack_reserve.map(|bytes| bytes.to_string()).unwrap_or_default())
        .stdin(Stdio::null())
        .output()
        .map_err(|error| format!("cannot run cargo: {error}"))?;
    if !output.status.success() {
        let stderr = String::from_utf8_lossy(&output.stderr);
        return Err(match build_failure(&stderr) {
            Some(reason) => format!("building the firmware failed: {reason}\n{stderr}"),
            None => format!("building the firmware failed:\n{stderr}"),
        });
    }
    Ok(target_dir.join(options.board.rust_target()).join("release/microtrace-firmware"))
}

/// The line that says why a build failed, when it is one of the firmware's own: build.rs's
/// `error: ...` (a bad scene, a capacity) or the RAM check's `evaluation panicked: ...`
/// (firmware/src/ram.rs).
fn build_failure(stderr: &str) -> Option<String> {
    stderr.lines().find_map(|line| {
        let line = line.trim();
        if let Some((_, message)) = line.split_once("evaluation panicked: ") {
            return Some(message.to_owned());
        }
        line.strip_prefix("error: ")
            .filter(|message| !message.starts_with("failed to run custom build command") && !message.starts_with("could not compile"))
            .map(str::to_owned)
    })
}

fn run_qemu(options: &FirmwareOptions, elf: &Path, out: &Path, plugin_arguments: &str) -> Result<(), String> {
    let machine = options.board.machine();
    if !options.board.shows(options.size) {
        let mut run = QemuRun::start(machine, elf, out, plugin_arguments, None, options.timeout)?;
        let status = run.wait()?;
        if !status.success() {
            return Err(format!("the firmware failed ({status}); QEMU's output:\n{}", run.output()));
        }
        return Ok(());
    }

    // With a display: the firmware holds its picture until we have taken the screendump
    // (board/stellaris.rs); a socket path must be short, so it lives in the temp dir.
    touch(&out.join("screendump.wanted"))?;
    let socket = std::env::temp_dir().join(format!("microtrace-monitor-{}-{}.sock", std::process::id(), unique()));
    let _ = std::fs::remove_file(&socket);
    let result = (|| {
        let mut run = QemuRun::start(machine, elf, out, plugin_arguments, Some(&socket), options.timeout)?;
        if let Err(error) = run.wait_for_output("microtrace: waiting for screendump") {
            // A firmware that stopped early (a panic, a fault) says why in its output.
            return Err(match run.exited()? {
                Some(status) if !status.success() => format!("the firmware failed ({status}); QEMU's output:\n{}", run.output()),
                _ => error,
            });
        }
        let mut monitor = Monitor::connect(&socket, Duration::from_secs(10))?;
        let answer = monitor.command("screendump oled.ppm")?;
        let ppm_path = out.join("oled.ppm");
        let ppm = std::fs::read(&ppm_path).map_err(|error| format!("screendump gave no picture ({error}); the monitor said: {answer}"))?;
        touch(&out.join("screendump.done"))?;
        let status = run.wait()?;
        if !status.success() {
            return Err(format!("the firmware failed ({status}); QEMU's output:\n{}", run.output()));
        }
        let image = oled::downsample_screendump(&ppm)?;
        oled::write_png(&out.join("oled.png"), &image)?;
        let _ = std::fs::remove_file(&ppm_path);
        Ok(())
    })();
    let _ = std::fs::remove_file(&socket);
    let _ = std::fs::remove_file(out.join("screendump.wanted"));
    let _ = std::fs::remove_file(out.join("screendump.done"));
    result
}

fn unique() -> u64 {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(0);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

fn touch(path: &Path) -> Result<(), String> {
    std::fs::write(path, b"").map_err(|error| format!("{}: {error}", path.display()))
}

fn read_key_values(path: &Path) -> Result<BTreeMap<String, String>, String> {
    let text = std::fs::read_to_string(path).map_err(|error| format!("{}: {error}", path.display()))?;
    Ok(text
        .lines()
        .filter_map(|line| line.split_once('='))
        .map(|(key, value)| (key.trim().to_owned(), value.trim().to_owned()))
        .collect())
}

/// A flat JSON object: the names as strings, then the integers.
fn json(names: &BTreeMap<&str, String>, integers: &BTreeMap<String, u64>) -> String {
    let escape = |text: &str| text.replace('\\', "\\\\").replace('"', "\\\"");
    let mut fields: Vec<String> = names.iter().map(|(key, value)| format!("  \"{key}\": \"{}\"", escape(value))).collect();
    fields.extend(integers.iter().map(|(key, value)| format!("  \"{key}\": {value}")));
    format!("{{\n{}\n}}\n", fields.join(",\n"))
}

/// A few lines for the terminal.
pub fn summary(run: &FirmwareRun, options: &FirmwareOptions) -> String {
    let get = |key: &str| run.numbers.get(key).copied().unwrap_or(0);
    let mut text = format!(
        "{} on {} ({}): {} pixels, {} instructions per frame ({} per pixel; instructions, not cycles): prepare {}, render {}\n",
        options.scene.display(),
        options.board.name(),
        options.number,
        get("pixels"),
        get("frame_instructions"),
        get("frame_instructions_per_pixel"),
        get("prepare_instructions"),
        get("render_instructions"),
    );
    text += &format!(
        "flash {} bytes, static RAM {} bytes, peak stack {} bytes\n",
        get("flash_bytes"),
        get("static_ram_bytes"),
        get("stack_peak_bytes")
    );
    text += &format!(
        "rays traced {}, intersected {}, ray-object tests {}, shadow rays {}, shadow tests {}\n",
        get("rays_traced"),
        get("rays_intersected"),
        get("ro_tests"),
        get("shadow_rays"),
        get("shadow_tests")
    );
    if options.progressive {
        text += &format!(
            "progressive: rays traced per pass (8x8, 4x4, 2x2, 1x1) {}, {}, {}, {}\n",
            get("pass1_rays_traced"),
            get("pass2_rays_traced"),
            get("pass3_rays_traced"),
            get("pass4_rays_traced")
        );
    }
    for (what, symbols) in [("f64 routines", &run.audit.f64), ("panic symbols", &run.audit.panic), ("core::fmt symbols", &run.audit.fmt)] {
        let names: Vec<&str> = symbols.iter().map(|symbol| symbol.demangled.as_str()).collect();
        text += &format!("linked: {} {what}{}{}\n", names.len(), if names.is_empty() { "" } else { ": " }, names.join(", "));
    }
    text += &format!("wrote {}", options.out.display());
    text
}
