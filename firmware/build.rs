//! Build script of the firmware:
//! 1. puts the selected board's `memory.x` where cortex-m-rt's `link.x` finds it;
//! 2. parses the scene named by `MICROTRACE_SCENE` with the same parser the host uses, fits it
//!    to the display (`fit_to_size`, as `microtrace render --size 128x64` does), applies the
//!    `MICROTRACE_OPT` override, checks the scene's primitives against the enabled features,
//!    and writes the scene as Rust constants into `OUT_DIR/scene.rs`.
//!
//! Environment (all optional):
//! - `MICROTRACE_SCENE`: absolute path of a `.mts` or `.nff` file (default: `../scenes/snooker.mts`).
//! - `MICROTRACE_NUMBER`: `f64`, `f32`, `fixed`, `fixed16`, `f32-micromath` or `soft32` (default `f32`).
//!   On the boards with an FPU (mps2-an386, Cortex-M4F; mps2-an505, Cortex-M33) `f32` is
//!   `F32With<VsqrtF32>`: the FPU's square root, the same results (fpu-sqrt/src/lib.rs).
//! - `MICROTRACE_SIZE`: `WIDTHxHEIGHT` of the render (default `128x64`, the OLED).
//! - `MICROTRACE_OPT`: `scene` (default: keep the scene's `optimize`), `all`, `none`, or a comma
//!   list of `pixelbuffer,extents,grid,sortlist`.
//! - `MICROTRACE_STACK_RESERVE`: the bytes of stack the RAM check keeps free (default: the
//!   budget's peak stack, 12288, or 6144 on the 16 KB micro:bit; src/ram.rs). Smaller lets a larger scene build; its stack may then
//!   overflow, which the firmware reports (src/fault.rs).
//! - `MICROTRACE_FAULT_TEST`: `1` builds the fault test (`cfg(microtrace_fault_test)`, src/fault.rs):
//!   the firmware then panics, hard-faults, takes an unexpected interrupt or overflows its stack
//!   when the host has a file `provoke-panic`, `provoke-hard-fault`,
//!   `provoke-unexpected-interrupt` or `provoke-stack-overflow` (`cargo xtask firmware
//!   --provoke`). Never set for a normal build, which links no panic path.
//!
//! The board's RAM and flash (origin and length, from its `memory.x`) go into `scene.rs` too:
//! src/ram.rs checks at compile time that the scene fits the RAM (a scene too large fails the
//! build with its size, before the linker could), src/fault.rs sets the MPU's regions from them.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use microtrace::bake::{Bake, BAKE_CAPACITY};
use microtrace::model::{Optimizations, Primitive, SceneDescription};
use microtrace::number::NumberKind;


fn main() {
    let manifest_dir = PathBuf::from(env("CARGO_MANIFEST_DIR").unwrap());
    let out_dir = PathBuf::from(env("OUT_DIR").unwrap());

    let board = select_board();
    let memory = copy_memory_layout(&manifest_dir, &out_dir, board);

    let scene_path = env("MICROTRACE_SCENE")
        .map(PathBuf::from)
        .unwrap_or_else(|| manifest_dir.join("../scenes/snooker.mts"));
    println!("cargo:rerun-if-changed={}", scene_path.display());
    for name in KNOWN_VARIABLES {
        println!("cargo:rerun-if-env-changed={name}");
    }
    refuse_unknown_variables();
    println!("cargo:rustc-check-cfg=cfg(microtrace_fault_test)");
    match env("MICROTRACE_FAULT_TEST").as_deref() {
        None | Some("0") => {}
        Some("1") => println!("cargo:rustc-cfg=microtrace_fault_test"),
        Some(other) => fail(&format!("MICROTRACE_FAULT_TEST={other}: expected 1 (the fault test) or 0")),
    }

    let number_name = env("MICROTRACE_NUMBER").unwrap_or_else(|| "f32".into());
    let bake = Bake { size: render_size(&env("MICROTRACE_SIZE").unwrap_or_else(|| "128x64".into())), number: number_kind(&number_name), f32_square_root: fpu_square_root(board) };

    let text = std::fs::read(&scene_path)
        .unwrap_or_else(|error| fail(&format!("cannot read the scene {}: {error}", scene_path.display())));
    println!("cargo:rustc-check-cfg=cfg(microtrace_sizing)");
    let parsed: Result<microtrace::model::SceneDescription<BAKE_CAPACITY>, _> = microtrace::parser::parse_file(&scene_path.to_string_lossy(), &text);
    let mut description = match parsed {
        Ok(description) => description,
        Err(error) if matches!(error.kind, microtrace::model::SceneErrorKind::TooManyObjects { .. }) => {
            return size_only(&scene_path, &text, &bake, board, &memory, &out_dir);
        }
        Err(error) => fail(&in_file(&scene_path, &error)),
    };
    if let Some(optimizations) = optimization_override(env("MICROTRACE_OPT").as_deref()) {
        description.optimizations = optimizations;
    }
    check_primitives(&description, &scene_path);

    // The scene baked in the number type: what the chip starts from (no f64 there).
    let baked = microtrace::bake::bake(&description, &bake).unwrap_or_else(|error| fail(&in_file(&scene_path, &error)));
    let mut source = board_facts(&scene_path, board);
    source.push_str(&baked);
    memory.write(&mut source);
    write_stack_reserve(&mut source);
    std::fs::write(out_dir.join("scene.rs"), source).unwrap();
}

/// The variables this build reads (the module's comment says what each does).
const KNOWN_VARIABLES: [&str; 6] = ["MICROTRACE_SCENE", "MICROTRACE_NUMBER", "MICROTRACE_SIZE", "MICROTRACE_OPT", "MICROTRACE_FAULT_TEST", "MICROTRACE_STACK_RESERVE"];

/// The project's other tools' variables, which a test run may pass on to this build.
const OTHER_TOOLS_VARIABLES: [&str; 5] = ["MICROTRACE_SEEDS", "MICROTRACE_REPLAY_DIR", "MICROTRACE_REPLAY_STRICT", "MICROTRACE_BUILD_ID", "MICROTRACE_PARENT_BUILD_ID"];

/// A `MICROTRACE_*` variable this build does not know is a typo (`MICROTRACE_NUMBR=fixed` would
/// otherwise build `f32` without a word): it stops the build, naming the known ones.
fn refuse_unknown_variables() {
    for (name, _) in std::env::vars_os() {
        let Some(name) = name.to_str() else { continue };
        if name.starts_with("MICROTRACE_") && !KNOWN_VARIABLES.contains(&name) && !OTHER_TOOLS_VARIABLES.contains(&name) {
            fail(&format!("{name}: not a variable the firmware's build reads (it reads {})", KNOWN_VARIABLES.join(", ")));
        }
    }
}

/// The stack the RAM check keeps (`MICROTRACE_STACK_RESERVE`).
fn write_stack_reserve(source: &mut String) {
    let reserve = match env("MICROTRACE_STACK_RESERVE") {
        None => "None".to_owned(),
        Some(text) => match text.parse::<u32>() {
            Ok(bytes) => format!("Some({bytes})"),
            Err(_) => fail("MICROTRACE_STACK_RESERVE: expected a number of bytes, e.g. 12288"),
        },
    };
    writeln!(source, "/// The stack the RAM check keeps free when `MICROTRACE_STACK_RESERVE` says (src/ram.rs; `None`: the").unwrap();
    writeln!(source, "/// default, which grows with the objects).").unwrap();
    writeln!(source, "pub const STACK_RESERVE_BYTES: Option<usize> = {reserve};").unwrap();
}

/// A scene of more objects than the build bakes ([`BAKE_CAPACITY`]; Haines' SPD scenes have
/// thousands): only its sizes are written (`microtrace::bake::bake_sizes`), and the build is
/// compiled with `cfg(microtrace_sizing)`, where firmware/src/ram.rs stops it with the RAM the
/// scene would need on the board (the same check, in the target's own layout), so a report can
/// say what such a scene needs. It never links.
fn size_only(scene_path: &Path, text: &[u8], bake: &Bake<'_>, board: Board, memory: &Memory, out_dir: &Path) {
    let parsed: Result<microtrace::model::Description<Vec<microtrace::model::ObjectDescription>>, _> = microtrace::parser::parse_file(&scene_path.to_string_lossy(), text);
    let description = parsed.unwrap_or_else(|error| fail(&in_file(scene_path, &error)));
    let mut source = board_facts(scene_path, board);
    source.push_str(&microtrace::bake::bake_sizes(&description, bake));
    memory.write(&mut source);
    write_stack_reserve(&mut source);
    writeln!(source, "/// The objects the build bakes at most (microtrace::bake::BAKE_CAPACITY).\npub const PREPARED_AHEAD_AT_MOST: usize = {BAKE_CAPACITY};").unwrap();
    println!("cargo:rustc-cfg=microtrace_sizing");
    std::fs::write(out_dir.join("scene.rs"), source).unwrap();
}

/// What the firmware says of its build beside the baked scene: the board and the scene's file.
fn board_facts(scene_path: &Path, board: Board) -> String {
    let scene_name = scene_path.file_name().map(|name| name.to_string_lossy().into_owned()).unwrap_or_default();
    let mut out = String::new();
    writeln!(out, "// Written by firmware/build.rs from {}: do not edit.", scene_path.display()).unwrap();
    writeln!(out, "pub const BOARD_NAME: &str = {:?};", board.name).unwrap();
    writeln!(out, "pub const SCENE_NAME: &str = {scene_name:?};").unwrap();
    writeln!(out, "/// The scene file as the build was given it, for messages.").unwrap();
    writeln!(out, "pub const SCENE_PATH: &str = {:?};", scene_path.display().to_string()).unwrap();
    out
}

fn env(name: &str) -> Option<String> {
    std::env::var(name).ok().filter(|value| !value.is_empty())
}

/// A scene error in the one format of every scene error (docs/bad-input.md): `FILE:line N:
/// reason`, or `FILE: reason` for an error tied to no line.
fn in_file(path: &Path, error: &microtrace::model::SceneError) -> String {
    if error.line == 0 {
        format!("{}: {error}", path.display())
    } else {
        format!("{}:{error}", path.display())
    }
}

/// Stops the build with `message` (cargo shows a failed build script's stderr).
fn fail(message: &str) -> ! {
    eprintln!("error: {message}");
    std::process::exit(1);
}

// The board table, shared with xtask: `BoardFacts`, `BOARDS`.
include!("boards.rs");

type Board = &'static BoardFacts;

fn select_board() -> Board {
    let enabled: Vec<Board> = BOARDS.iter().filter(|board| env(&format!("CARGO_FEATURE_{}", board.name.to_uppercase().replace('-', "_"))).is_some()).collect();
    let [board] = enabled[..] else {
        let names: Vec<String> = BOARDS.iter().map(|board| format!("`{}`", board.name)).collect();
        fail(&format!("enable exactly one board feature: {}", names.join(", ")))
    };
    for architecture in ["armv6m", "armv7m", "armv8m"] {
        println!("cargo:rustc-check-cfg=cfg({architecture})");
    }
    println!("cargo:rustc-cfg={}", board.architecture);
    board
}

fn copy_memory_layout(manifest_dir: &Path, out_dir: &Path, board: Board) -> Memory {
    // The repository root's memory.x describes the default board (boards.rs).
    let source = manifest_dir.join(board.memory_x);
    println!("cargo:rerun-if-changed={}", source.display());
    std::fs::copy(&source, out_dir.join("memory.x"))
        .unwrap_or_else(|error| fail(&format!("cannot copy {}: {error}", source.display())));
    // cortex-m-rt's `device` feature has its link.x include a device crate's `device.x`, the
    // interrupt handlers' weak aliases: there are none (src/vectors.rs).
    std::fs::write(out_dir.join("device.x"), "/* No device interrupt handlers: src/vectors.rs. */\n")
        .unwrap_or_else(|error| fail(&format!("cannot write device.x: {error}")));
    println!("cargo:rustc-link-search={}", out_dir.display());
    // cortex-m-rt's linker script (with memory.x); here rather than in .cargo/config.toml's
    // rustflags, which the examples below this folder would inherit.
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    let text = std::fs::read_to_string(&source)
        .unwrap_or_else(|error| fail(&format!("cannot read {}: {error}", source.display())));
    let region = |name: &str| {
        memory_region(&text, name)
            .unwrap_or_else(|| fail(&format!("{}: no `{name} : ORIGIN = ..., LENGTH = ...` line", source.display())))
    };
    Memory { flash: region("FLASH"), ram: region("RAM") }
}

/// The board's memory as its `memory.x` gives it: (origin, length in bytes) of each region.
struct Memory {
    flash: (u64, u64),
    ram: (u64, u64),
}

impl Memory {
    fn write(&self, out: &mut String) {
        writeln!(out, "/// The board's flash and RAM (its memory.x): the MPU's regions, the RAM check (src/ram.rs).").unwrap();
        // The M0 has no MPU: only the RAM check reads these there.
        writeln!(out, "#[cfg_attr(armv6m, allow(dead_code))]\npub const FLASH_ORIGIN: u32 = {:#010x};", self.flash.0).unwrap();
        writeln!(out, "#[cfg_attr(armv6m, allow(dead_code))]\npub const FLASH_BYTES: u32 = {};", self.flash.1).unwrap();
        writeln!(out, "#[cfg_attr(armv6m, allow(dead_code))]\npub const RAM_ORIGIN: u32 = {:#010x};", self.ram.0).unwrap();
        writeln!(out, "pub const RAM_BYTES: u32 = {};", self.ram.1).unwrap();
    }
}

/// `NAME : ORIGIN = 0x..., LENGTH = 64K` (decimal or hex, with an optional K or M) in a
/// memory.x's `MEMORY` block.
fn memory_region(text: &str, name: &str) -> Option<(u64, u64)> {
    let number = |text: &str| -> Option<u64> {
        let text = text.trim().trim_end_matches(',').trim();
        let (digits, scale) = match text.as_bytes().last()? {
            b'K' | b'k' => (&text[..text.len() - 1], 1024),
            b'M' | b'm' => (&text[..text.len() - 1], 1024 * 1024),
            _ => (text, 1),
        };
        let value = match digits.strip_prefix("0x").or_else(|| digits.strip_prefix("0X")) {
            Some(hex) => u64::from_str_radix(&hex.replace('_', ""), 16).ok()?,
            None => digits.parse().ok()?,
        };
        Some(value * scale)
    };
    text.lines().find_map(|line| {
        let (region, rest) = line.trim().split_once(':')?;
        if region.trim() != name {
            return None;
        }
        let (origin, length) = rest.split_once(',')?;
        let origin = number(origin.trim().strip_prefix("ORIGIN")?.trim().strip_prefix('=')?)?;
        let length = number(length.trim().strip_prefix("LENGTH")?.trim().strip_prefix('=')?)?;
        Some((origin, length))
    })
}

/// The number type (`MICROTRACE_NUMBER`), checking that the firmware feature it needs is on.
fn number_kind(name: &str) -> NumberKind {
    let Some(kind) = NumberKind::from_name(name) else {
        let names: Vec<&str> = NumberKind::ALL.iter().map(|kind| kind.name()).collect();
        let (last, rest) = names.split_last().unwrap_or((&"", &[]));
        fail(&format!("MICROTRACE_NUMBER={name}: expected {} or {last}", rest.join(", ")))
    };
    if let Some(feature) = kind.feature() {
        if env(&format!("CARGO_FEATURE_{}", feature.to_uppercase().replace('-', "_"))).is_none() {
            fail(&format!("MICROTRACE_NUMBER={name} needs the firmware feature `{feature}`"));
        }
    }
    kind
}

/// The Cortex-M4F's and M33's FPU has `vsqrt.f32`, which the core cannot emit (libm's `sqrtf`
/// is integer code there); it is correctly rounded, so the image is plain f32's
/// (fpu-sqrt/src/lib.rs). Only with the hard-float ABI (an FPU); the M3 and M0 have none.
fn fpu_square_root(board: Board) -> Option<&'static str> {
    let hard_float = env("CARGO_CFG_TARGET_ABI").as_deref() == Some("eabihf");
    (board.fpu_square_root && hard_float).then_some("microtrace_fpu_sqrt::VsqrtF32")
}

fn render_size(text: &str) -> (u16, u16) {
    let parsed = text.split_once('x').and_then(|(w, h)| Some((w.parse().ok()?, h.parse().ok()?)));
    match parsed {
        Some((width, height)) if width > 0 && height > 0 => (width, height),
        _ => fail(&format!("MICROTRACE_SIZE={text}: expected WIDTHxHEIGHT, e.g. 128x64")),
    }
}

/// `None` keeps the scene's own `optimize` statement.
fn optimization_override(text: Option<&str>) -> Option<Optimizations> {
    match text? {
        "scene" => None,
        list => Some(Optimizations::from_list(list).unwrap_or_else(|other| {
            fail(&format!(
                "MICROTRACE_OPT: unknown optimization `{other}` (expected all, none, or a list of pixelbuffer,extents,grid,sortlist)"
            ))
        })),
    }
}

/// The firmware models only the primitives its features enable; a scene that needs another
/// must not build (it would otherwise fail at run time in `prepare`).
fn check_primitives<const N: usize>(description: &SceneDescription<N>, scene_path: &Path) {
    for primitive in Primitive::ALL {
        let feature = format!("CARGO_FEATURE_{}", primitive.name().to_uppercase());
        let enabled = env(&feature).is_some();
        if let Some((_, line)) = description.primitives().find(|(used, _)| used.index() == primitive.index()) {
            if !enabled {
                fail(&format!(
                    "{}:line {line}: the scene uses a {name} but the firmware was built without the `{name}` feature; \
                     enable it (`cargo xtask firmware` picks the features from the scene)",
                    scene_path.display(),
                    name = primitive.name()
                ));
            }
        }
    }
    // Solids likewise (constructive solid geometry, thesis chapter 3).
    if let Some(solid) = description.objects.iter().find(|object| matches!(object.primitive, Primitive::Solid(_))) {
        if env("CARGO_FEATURE_CSG").is_none() {
            fail(&format!(
                "{}:line {}: the scene has a solid but the firmware was built without the `csg` feature; \
                 enable it (`cargo xtask firmware` picks the features from the scene)",
                scene_path.display(),
                solid.line
            ));
        }
    }
    // Antialiasing likewise (chapter 5).
    if description.antialias.is_some() && env("CARGO_FEATURE_ANTIALIAS").is_none() {
        fail(&format!(
            "{}:line {}: the scene antialiases but the firmware was built without the `antialias` feature; \
             enable it (`cargo xtask firmware` picks the features from the scene)",
            scene_path.display(),
            description.lines.antialias
        ));
    }
    // The ray tree likewise (chapter 5): a scene whose objects reflect or transmit needs it.
    if let Some(object) = description.objects.iter().find(|object| object.material.spawns_rays()) {
        if env("CARGO_FEATURE_RAY_TREE").is_none() {
            fail(&format!(
                "{}:line {}: the object reflects or transmits but the firmware was built without the `ray-tree` feature; \
                 enable it (`cargo xtask firmware` picks the features from the scene)",
                scene_path.display(),
                object.line
            ));
        }
    }
}
