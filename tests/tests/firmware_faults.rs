//! The firmware fails loudly (firmware/README.md, "When it fails"), on every board:
//! - a panic, a hard fault, an unexpected interrupt and a stack overflow, each provoked by the fault test
//!   (`MICROTRACE_FAULT_TEST=1`, `cargo xtask firmware --provoke`), end the QEMU run with exit
//!   status 1 and the firmware's message naming what happened, well before the timeout;
//! - the stack lies below the statics (flip-link), from the start of RAM, so an overflow runs
//!   off RAM (where the MPU faults, or on the micro:bit's M0, which has none, the bus) and never
//!   through the prepared scene; a real scene that
//!   leaves too little stack (the build's stack reserve set to 0) stops with "stack overflow";
//! - a scene too large for the chip's RAM fails at build time with the RAM it needs, part by
//!   part, and the board's RAM, not with rust-lld's `will not fit in region 'RAM'`;
//! - a scene with more objects than the build's capacity fails, naming the file, the line and
//!   the capacity, in xtask and in firmware/build.rs alike.
//!
//! One fault-test build per board serves all four faults (the firmware picks the fault from a
//! file xtask leaves in QEMU's directory); the scenes too large fail before code generation.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use xtask::firmware::{self, Board, Fault, FirmwareOptions, FIRMWARE_SCENE_CAPACITY};

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes").join(name)
}

fn work_dir(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware-faults").join(name)
}

/// The RAM each board's memory.x gives the firmware: (origin, bytes).
fn ram(board: Board) -> (u64, u64) {
    match board {
        Board::Lm3s6965evb | Board::Mps2An386 | Board::Netduinoplus2 => (0x2000_0000, 64 * 1024),
        Board::Microbit => (0x2000_0000, 16 * 1024),
        Board::Lm3s811evb => (0x2000_0000, 8 * 1024),
        // The Secure alias of SSRAM2 (firmware/src/board/mps2_an505/memory.x).
        Board::Mps2An505 => (0x3800_0000, 64 * 1024),
    }
}

/// What each provoked fault must print (the start of the firmware's line).
fn expected_message(fault: Fault, board: Board) -> Vec<&'static str> {
    match (fault, board) {
        (Fault::Panic, _) => vec!["microtrace: panic: provoked by the fault test (provoke-panic) at src/fault.rs:"],
        // The M0 has no MPU and no fault status registers: a bus error, said as much.
        (Fault::HardFault, Board::Microbit) => vec![
            "microtrace: hard fault at PC 0x",
            ": no fault status registers on ARMv6-M: a bus error (an access outside the memory map)",
        ],
        (Fault::HardFault, _) => vec![
            "microtrace: hard fault at PC 0x",
            ": data access outside the flash, RAM and peripherals (MemManage), at address 0x44444444 (CFSR 0x00000082, HFSR 0x40000000)",
        ],
        // PendSV is exception 14, IRQ number 14 - 16.
        (Fault::UnexpectedInterrupt, _) => vec!["microtrace: unexpected exception or interrupt, IRQ number -2\n"],
        // Without fault status registers, the M0's handler knows the overflow by the frame's place.
        (Fault::StackOverflow, Board::Microbit) => vec![
            "microtrace: stack overflow: the stack grew below its bottom, the start of RAM at 0x20000000; it has ",
            " bytes, what the RAM leaves below the statics, which it cannot reach (flip-link)",
        ],
        (Fault::StackOverflow, Board::Mps2An505) => vec![
            "microtrace: stack overflow: the stack grew below its bottom, the start of RAM at 0x38000000 (an access at 0x37ff",
            " bytes, what the RAM leaves below the statics, which it cannot reach (flip-link)",
        ],
        (Fault::StackOverflow, _) => vec![
            "microtrace: stack overflow: the stack grew below its bottom, the start of RAM at 0x20000000 (an access at 0x1fff",
            " bytes, what the RAM leaves below the statics, which it cannot reach (flip-link)",
        ],
    }
}

fn faults_fail_loudly(board: Board) {
    for fault in Fault::ALL {
        let out = work_dir(&format!("{}-{}", board.name(), fault.name()));
        let mut options = FirmwareOptions::new(scene_path("snooker.mts"), board, "f32", &out);
        options.provoke = Some(fault);
        options.timeout = Duration::from_secs(60);
        let started = Instant::now();
        let error = match firmware::run(&options) {
            Ok(_) => panic!("{} on {}: the run succeeded", fault.name(), board.name()),
            Err(error) => error,
        };
        let context = format!("{} on {}: {error}", fault.name(), board.name());
        println!("{context}");
        // QEMU's exit status is the firmware's semihosting exit: failure, 1.
        assert!(error.contains("the firmware failed (exit status: 1); QEMU's output:"), "{context}");
        for text in expected_message(fault, board) {
            assert!(error.contains(text), "{context}\n(expected {text:?})");
        }
        assert!(!error.contains("timed out"), "{context}");
        // Build and run, not a wait for the timeout (a cached build runs in well under a second).
        assert!(started.elapsed() < Duration::from_secs(50), "{context}: took {:?}", started.elapsed());

        let elf = std::fs::read(out.join("firmware.elf")).unwrap();
        if fault == Fault::HardFault {
            // The PC named is the faulting store's: within the firmware's code.
            let pc = error.split("hard fault at PC 0x").nth(1).and_then(|rest| u64::from_str_radix(rest.get(..8)?, 16).ok());
            let code_start = symbol(&elf, "__stext");
            let code_end = symbol(&elf, "__etext");
            assert!(pc.is_some_and(|pc| pc >= code_start && pc < code_end), "{context}: PC {pc:?} outside the code ({code_start:#x} to {code_end:#x})");
        }
        if fault == Fault::StackOverflow {
            // The size it names is the ELF's stack: from the start of RAM to the lowest static.
            let size = symbol(&elf, "_stack_start") - symbol(&elf, "_stack_end");
            assert!(error.contains(&format!("; it has {} bytes,", grouped(size))), "{context}\n(expected the stack's {size} bytes)");
        }
        stack_is_below_the_statics(&elf, board);
    }
}

fn symbol(elf: &[u8], name: &str) -> u64 {
    xtask::elf::function_address(elf, name).unwrap_or_else(|error| panic!("{error}"))
}

/// 42856 as "42,856".
fn grouped(value: u64) -> String {
    let digits = value.to_string();
    let mut text = String::new();
    for (index, digit) in digits.chars().enumerate() {
        if index > 0 && (digits.len() - index).is_multiple_of(3) {
            text.push(',');
        }
        text.push(digit);
    }
    text
}

/// flip-link's layout: the stack runs from its top down to the start of RAM, and every static
/// (.data, .bss) lies above its top.
fn stack_is_below_the_statics(elf: &[u8], board: Board) {
    let symbol = |name: &str| symbol(elf, name);
    let (ram_origin, ram_bytes) = ram(board);
    let (top, bottom) = (symbol("_stack_start"), symbol("_stack_end"));
    assert_eq!(bottom, ram_origin, "{}: the stack's bottom is the start of RAM", board.name());
    for statics in ["__sdata", "__sbss"] {
        assert!(symbol(statics) >= top, "{}: {statics} at {:#x} is below the stack's top {top:#x}", board.name(), symbol(statics));
    }
    assert!(symbol("__ebss") <= ram_origin + ram_bytes, "{}: .bss ends beyond the RAM", board.name());
}

#[test]
fn faults_on_lm3s6965evb_fail_loudly() {
    faults_fail_loudly(Board::Lm3s6965evb);
}

#[test]
fn faults_on_mps2_an386_fail_loudly() {
    faults_fail_loudly(Board::Mps2An386);
}

#[test]
fn faults_on_microbit_fail_loudly() {
    faults_fail_loudly(Board::Microbit);
}

#[test]
fn faults_on_mps2_an505_fail_loudly() {
    faults_fail_loudly(Board::Mps2An505);
}

/// A scene of `count` spheres on a table, `LINES_PER_SPHERE` lines each after the header.
fn many_spheres(count: usize) -> PathBuf {
    let mut text = String::from(
        "# generated by tests/firmware_faults.rs\n\
         viewport 0 527 0 479\n\
         window -400 400 -300 300\n\
         viewplane 1000\n\
         perspective 0 300 1500\n\
         light point 300 1400 900\n\
         ambient 0.2\n\
         shadows on\n\
         group 1 15 1 1 up\n",
    );
    for index in 0..count {
        let (x, z) = ((index % 25) as f64 * 30.0 - 360.0, (index / 25) as f64 * 30.0);
        text += &format!("sphere\n  scale 12 12 12\n  translate {x} 12 {z}\n  colour 1\n");
    }
    // Tests running side by side write the same scene: each writes its own file and renames it
    // into place, so no build ever reads a half-written scene (a truncated file parses as fewer
    // spheres, which once gave a smaller stack than expected).
    let path = work_dir("scenes").join(format!("many-{count}.mts"));
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    let unique = path.with_extension(format!("{:?}.partial", std::thread::current().id()).replace(['(', ')'], ""));
    std::fs::write(&unique, text).unwrap();
    std::fs::rename(&unique, &path).unwrap();
    path
}

/// The integer after `label` in `text` ("65,536" reads 65536).
fn number_after(text: &str, label: &str) -> u64 {
    let rest = text.split(label).nth(1).unwrap_or_else(|| panic!("no {label:?} in {text}"));
    let digits: String = rest.chars().take_while(|c| c.is_ascii_digit() || *c == ',').filter(char::is_ascii_digit).collect();
    digits.parse().unwrap_or_else(|_| panic!("no number after {label:?} in {text}"))
}

/// 512 spheres (the most the build bakes) rendered at 320x240 into a framebuffer need
/// about 90 KB: 75 KB of framebuffer, the budget's 12 KB of stack and the prepared scene, which
/// no longer grows with the objects (every table of the view, the grid, the shadow tables and
/// the hierarchy are made at build time, in flash): more than either board's 64 KB. The build
/// stops in the firmware's compile-time RAM check, with the parts that add up.
fn a_scene_too_large_fails_at_build_time(board: Board) {
    let scene = many_spheres(TOO_MANY);
    let mut options = FirmwareOptions::new(&scene, board, "f32", work_dir(&format!("{}-too-large", board.name())));
    options.framebuffer = true;
    options.size = (320, 240);
    let error = firmware::run(&options).unwrap_err();
    let context = format!("{}: {error}", board.name());
    println!("{}", error.lines().next().unwrap_or_default());
    let line = error.lines().next().unwrap_or_default();
    assert!(line.starts_with(&format!("building the firmware failed: {}: needs ", scene.display())), "{context}");
    assert!(line.contains(&format!(" for {TOO_MANY} objects in f32, framebuffer 76,800 for 320x240, stack reserve ")), "{context}");
    assert!(line.contains(&format!("), the {} has 65,536 (firmware/README.md, \"When it fails\")", board.name())), "{context}");
    assert!(!error.contains("will not fit in region"), "{context}: the linker ran");

    let needed = number_after(line, ": needs ");
    let parts = ["the prepared scene ", "framebuffer ", "stack reserve "].map(|label| number_after(line, label));
    assert_eq!(parts.iter().sum::<u64>(), needed, "{context}: the parts do not add up");
    assert!(needed > 64 * 1024, "{context}");
    // A byte a pixel; the stack reserve is the budget's 12 KB.
    assert_eq!(parts[1], 320 * 240, "{context}");
    assert_eq!(parts[2], 12 * 1024, "{context}");
    // The prepared scene does not grow with the objects: all of it is in flash.
    assert!(parts[0] < 2 * 1024, "{context}");
}

/// Spheres too many for either board's RAM.
const TOO_MANY: usize = 512;

#[test]
fn a_scene_too_large_for_the_lm3s6965evb_fails_at_build_time() {
    a_scene_too_large_fails_at_build_time(Board::Lm3s6965evb);
}

#[test]
fn a_scene_too_large_for_the_mps2_an386_fails_at_build_time() {
    a_scene_too_large_fails_at_build_time(Board::Mps2An386);
}

/// A real scene whose statics leave too little stack (the RAM check's reserve set to 0): 512
/// spheres with a framebuffer of 256 x `rows` (64 KB of statics leave 1 to 2 KB of stack; the
/// render's peak is about 2 KB in the Cortex-M4F's `f32`, 2.4 KB in the M3's software `f32`):
/// the stack overflows, a frame jumping past the bottom of RAM at once (a guard of a few words
/// would miss it), and the run says so. On the lm3s6965evb this is what used to hang until the
/// timeout.
fn a_scene_that_overflows_its_stack_says_so(board: Board, objects: usize, rows: u16) {
    let scene = many_spheres(objects);
    let out = work_dir(&format!("{}-overflowing-{objects}", board.name()));
    let mut options = FirmwareOptions::new(&scene, board, "f32", &out);
    options.stack_reserve = Some(0);
    options.framebuffer = true;
    options.size = (256, rows);
    options.timeout = Duration::from_secs(60);
    let error = firmware::run(&options).unwrap_err();
    let context = format!("{} with {objects} spheres: {error}", board.name());
    println!("{context}");
    assert!(error.contains("the firmware failed (exit status: 1); QEMU's output:"), "{context}");
    assert!(error.contains("microtrace: stack overflow: the stack grew below its bottom, the start of RAM at 0x20000000"), "{context}");
    let elf = std::fs::read(out.join("firmware.elf")).unwrap();
    let size = symbol(&elf, "_stack_start") - symbol(&elf, "_stack_end");
    // Less than the check would keep (its 12 KB budget), more than a few frames.
    assert!((1024..12 * 1024).contains(&size), "{context}: a stack of {size} bytes");
    assert!(error.contains(&format!("; it has {} bytes,", grouped(size))), "{context}");
    stack_is_below_the_statics(&elf, board);
}

#[test]
fn a_scene_that_overflows_its_stack_on_lm3s6965evb_says_so() {
    // 512, the build's capacity, since the objects stay in flash (149 before, 119 before the
    // framebuffer and the OLED copy left the RAM; with a framebuffer again since the shadow
    // tables left the stack).
    a_scene_that_overflows_its_stack_says_so(Board::Lm3s6965evb, FIRMWARE_SCENE_CAPACITY, 246);
}

#[test]
fn a_scene_that_overflows_its_stack_on_mps2_an386_says_so() {
    // Three rows more than on the lm3s6965evb: its render's peak stack is smaller (the FPU's
    // `f32`; 129 spheres before, when the lm3s6965evb's OLED copy took 4 KB more there; 246 rows
    // before the baked scene's statics fell from 1,128 bytes to about 330).
    a_scene_that_overflows_its_stack_says_so(Board::Mps2An386, FIRMWARE_SCENE_CAPACITY, 249);
}

/// One object more than the build's capacity: the build sizes the scene instead of baking it
/// (firmware/build.rs's `size_only`, `microtrace::bake::bake_sizes`) and stops at the RAM check
/// with the bytes the scene would need for its 513 objects (with a framebuffer of 256x246, more
/// than the board has: a baked scene of 513 spheres alone would fit), through xtask and through
/// the build script alone.
#[test]
fn a_scene_over_the_build_capacity_is_sized_and_says_what_it_needs() {
    let count = FIRMWARE_SCENE_CAPACITY + 1;
    let scene = many_spheres(count);
    let expected = format!("{}: needs ", scene.display());
    let sized = " bytes of RAM (the prepared scene ";
    let objects = format!(" for {count} objects in f32, framebuffer 62,976 for 256x246, stack reserve ");
    let mut options = FirmwareOptions::new(&scene, Board::Lm3s6965evb, "f32", work_dir("over-capacity"));
    options.framebuffer = true;
    options.size = (256, 246);
    for error in [firmware::run(&options).unwrap_err(), firmware::build_with_primitives(&options, &["sphere"]).unwrap_err()] {
        println!("{error}");
        assert!(error.contains(&expected) && error.contains(sized) && error.contains(&objects) && error.contains("the lm3s6965evb has 65,536"), "{error}");
    }
}

/// A `MICROTRACE_*` variable the firmware's build does not read is a typo, not a silent default:
/// the build stops, naming it and the variables it reads (firmware/build.rs).
#[test]
fn an_unknown_microtrace_variable_stops_the_build() {
    let firmware = xtask::firmware_dir();
    let output = std::process::Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .args(["build", "--release", "--quiet"])
        .arg("--target-dir")
        .arg(firmware.join("target"))
        .current_dir(&firmware)
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env("MICROTRACE_NUMBR", "fixed")
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(!output.status.success(), "the build ignored MICROTRACE_NUMBR");
    assert!(stderr.contains("MICROTRACE_NUMBR: not a variable the firmware's build reads (it reads MICROTRACE_SCENE, MICROTRACE_NUMBER,"), "{stderr}");
}
