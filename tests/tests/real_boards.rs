//! The real-board examples (firmware/examples/: a Raspberry Pi Pico with an SSD1306, one with an
//! ST7789, and a Pico 2 with the ST7789) build into complete images for their chips. For the
//! RP2040: boot2 at the flash's start, the vector table after it at 0x1000_0100 with its stack
//! pointer in RAM and its reset vector in `.text` (and the ELF's entry there too), kilobytes of
//! `.text`, the render's functions linked, and flash and RAM within the chip (2 MB flash, 264 KB
//! RAM). For the RP2350: the vector table at the flash's start and the boot ROM's IMAGE_DEF block
//! (a Secure Arm executable) in its first 4 KB, the same checks otherwise (4 MB flash, 520 KB
//! RAM), and the FPU doing the render's arithmetic. An image linked without cortex-m-rt's
//! `link.x` (the Pico example's state before: `.boot2` alone) fails these checks.
//!
//! Here the images are checked; `pico_emulated.rs` runs them in an RP2040 emulator.

use xtask::example::{self, Example, ImageReport};
use xtask::uf2;

/// Builds the example and checks its image; returns the report.
fn build_and_check(example: &Example, symbols: &[&str]) -> ImageReport {
    let elf = example::build(example).unwrap_or_else(|error| panic!("{error}"));
    let bytes = std::fs::read(&elf).unwrap_or_else(|error| panic!("{}: {error}", elf.display()));
    // 16 KB of code at least: the tracer, the HAL, the display's driver.
    let report = example::check_image(&bytes, example.chip, 16 * 1024, symbols)
        .unwrap_or_else(|problems| panic!("{}:\n  {}", elf.display(), problems.join("\n  ")));
    scene_is_baked(example, &bytes);
    eprintln!("{}: {report:?}", example.folder);
    uf2_holds_the_image(example, &elf, &bytes);
    report
}

/// The scene is baked (build.rs, `microtrace::bake`): its objects are in flash and the chip links
/// neither the parser nor the preparation from a description.
fn scene_is_baked(example: &Example, elf: &[u8]) {
    let (symbols, _) = xtask::elf::flash_symbols(elf).unwrap();
    assert!(symbols.iter().any(|symbol| symbol.demangled.ends_with("::scene::OBJECTS")), "{}: no baked objects in flash", example.folder);
    for code in ["microtrace::parser::", "prepare_in_place", "prepare_objects"] {
        assert!(!symbols.iter().any(|symbol| symbol.demangled.contains(code)), "{}: `{code}` is linked", example.folder);
    }
}

/// The UF2 file beside the ELF (what a user drags onto the Pico in BOOTSEL mode): every block
/// one the boot ROM takes (magic numbers, the chip's family, 256 bytes at a 256-byte boundary
/// of the flash, numbered in order), and every byte the ELF loads is in it, at its load address.
fn uf2_holds_the_image(example: &Example, elf: &std::path::Path, elf_bytes: &[u8]) {
    let path = example::uf2_path(elf);
    let file = std::fs::read(&path).unwrap_or_else(|error| panic!("{}: {error}", path.display()));
    let blocks = uf2::blocks(&file, example.chip.uf2_family).unwrap_or_else(|problems| panic!("{}:\n  {}", path.display(), problems.join("\n  ")));
    let pages: std::collections::BTreeMap<u64, Vec<u8>> = blocks.iter().cloned().collect();
    assert_eq!(pages.len(), blocks.len(), "{}: a page written twice", path.display());
    for (address, _) in &blocks {
        assert!(example.chip.flash.contains(address), "{}: a block at 0x{address:08x}, outside the flash", path.display());
    }
    let mut loaded = 0;
    for (address, bytes) in uf2::loadable(elf_bytes).unwrap() {
        for (at, byte) in (address..).zip(bytes) {
            let page = at - at % uf2::PAYLOAD_BYTES as u64;
            let written = pages.get(&page).and_then(|payload| payload.get((at - page) as usize));
            assert_eq!(written, Some(&byte), "{}: the byte at 0x{at:08x}", path.display());
            loaded += 1;
        }
    }
    assert!(loaded >= 16 * 1024, "{}: {loaded} bytes loaded", path.display());
    eprintln!("{}: {} blocks for {loaded} bytes", path.display(), blocks.len());
}

/// The render is kilobytes of code, not a stub: the example's out-of-line `render` is linked,
/// and the largest of the core's render functions it calls (the pixel loop, `render::trace`,
/// out of line since the render also dispatches to antialiasing) is at least a kilobyte.
fn render_is_real(report: &ImageReport, render: &str) {
    let size = |wanted: &str| report.symbols.iter().find(|(name, _)| name == wanted).map_or(0, |(_, size)| *size);
    assert!(size(render) > 0, "`{render}` is not linked");
    let core = size("microtrace::render::");
    assert!(size(render).max(core) >= 1024, "`{render}` is {} bytes, the largest `microtrace::render::` function {core}", size(render));
}

#[test]
fn the_pico_ssd1306_image_is_complete() {
    let render = "microtrace_pico_ssd1306::render";
    let report = build_and_check(&example::PICO_SSD1306, &[render, "microtrace::render::", "microtrace::shapes::sphere::"]);
    render_is_real(&report, render);
    // The 8 KB framebuffer (128 x 64 palette indices) is in RAM.
    assert!(report.static_ram_bytes >= 128 * 64, "{} bytes of static RAM", report.static_ram_bytes);
}

#[test]
fn the_pico_st7789_image_is_complete() {
    let render = "microtrace_pico_st7789::render";
    let report = build_and_check(&example::PICO_ST7789, &[render, "microtrace::render::", "microtrace::shapes::sphere::"]);
    render_is_real(&report, render);
    // The 56 KB framebuffer (240 x 240 palette indices) is in RAM.
    assert!(report.static_ram_bytes >= 240 * 240, "{} bytes of static RAM", report.static_ram_bytes);
}

#[test]
fn the_pico2_st7789_image_is_complete() {
    let render = "microtrace_pico2_st7789::render";
    // (The sphere's intersection is inlined into the render here: no function of its own.)
    let report = build_and_check(&example::PICO2_ST7789, &[render, "microtrace::render::"]);
    render_is_real(&report, render);
    assert!(report.static_ram_bytes >= 240 * 240, "{} bytes of static RAM", report.static_ram_bytes);
    // The vector table at the flash's start, the IMAGE_DEF after it (check_image); and `f32` in
    // the FPU: the render's code multiplies and adds in single-precision registers, and takes
    // its square roots with `vsqrt.f32` (firmware/fpu-sqrt).
    assert_eq!(report.reset_vector & 0xff00_0000, 0x1000_0000);
    let elf = example::build(&example::PICO2_ST7789).unwrap_or_else(|error| panic!("{error}"));
    // llvm-objdump decodes the FPU's instructions when told the M33's FPU is there.
    let output = std::process::Command::new(xtask::setup::llvm_tool("llvm-objdump"))
        .args(["-d", "--no-show-raw-insn", "--mattr=+fp-armv8d16sp"])
        .arg(&elf)
        .output()
        .unwrap_or_else(|error| panic!("llvm-objdump: {error}"));
    assert!(output.status.success(), "llvm-objdump: {}", String::from_utf8_lossy(&output.stderr));
    let listing = String::from_utf8_lossy(&output.stdout);
    let count = |mnemonics: &[&str]| listing.lines().filter(|line| mnemonics.iter().any(|mnemonic| line.contains(mnemonic))).count();
    let arithmetic = count(&["vmul.f32", "vadd.f32", "vfma.f32", "vsub.f32"]);
    assert!(arithmetic > 100, "{arithmetic} single-precision multiplies and adds in the image");
    assert!(count(&["vsqrt.f32"]) > 0, "no vsqrt.f32 in the image");
}

/// A Pico 2 image whose IMAGE_DEF is missing is not booted by the RP2350's ROM: the check names
/// it (here the Pico's image, checked as if for the RP2350).
#[test]
fn the_check_fails_an_rp2350_image_without_its_image_def() {
    let elf = example::build(&example::PICO_ST7789).unwrap_or_else(|error| panic!("{error}"));
    let bytes = std::fs::read(&elf).unwrap();
    let problems = example::check_image(&bytes, &example::RP2350, 1024, &[]).unwrap_err();
    assert!(problems.iter().any(|problem| problem.contains("no `.start_block` section")), "{problems:?}");
    assert!(problems.iter().any(|problem| problem.contains("vector table is at 0x10000100, not at 0x10000000")), "{problems:?}");
}

/// The check itself fails an image that is not for the chip, naming each problem, and names a
/// missing function. (The Pico example's image from before `-Tlink.x` was passed, `.boot2`
/// alone, fails with: `.boot2` not at 0x10000000, `.text` 0 bytes, no `.vector_table`, sections
/// outside the flash, the render's functions missing.)
#[test]
fn the_check_fails_an_image_not_for_the_chip() {
    let elf = example::build(&example::PICO_SSD1306).unwrap_or_else(|error| panic!("{error}"));
    let bytes = std::fs::read(&elf).unwrap();
    // Wrong chip: the same image does not fit a chip whose flash and RAM are elsewhere.
    let elsewhere = example::Chip {
        name: "elsewhere",
        flash: 0..0x4_0000,
        vector_table: 0,
        boot2: None,
        ram: 0x2000_0000..0x2001_0000,
        uf2_family: 0,
        image_def: None,
        rust_target: "thumbv6m-none-eabi",
    };
    let problems = example::check_image(&bytes, &elsewhere, 1024, &[]).unwrap_err();
    assert!(problems.iter().any(|problem| problem.contains("vector table is at 0x10000100")), "{problems:?}");
    assert!(problems.iter().any(|problem| problem.contains("not within the flash")), "{problems:?}");
    // A missing function is named.
    let problems = example::check_image(&bytes, example::PICO_SSD1306.chip, 1024, &["no_such_function_here"]).unwrap_err();
    assert_eq!(problems, ["no function `no_such_function_here` in the image"]);
}
