//! `cargo xtask firmware-example`: builds (does not run) the real-board examples in
//! firmware/examples/ (each a cargo workspace of its own), each ELF with its UF2 file beside it
//! (`crate::uf2`), and [`check_image`]: what the tests check in their ELFs (a complete image for
//! the chip, not just a boot block).

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use object::{Object, ObjectSection, ObjectSymbol, SectionFlags, SectionKind};

/// A real-board example: its folder under firmware/examples/ and its binary's name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Example {
    pub folder: &'static str,
    pub binary: &'static str,
    pub chip: &'static Chip,
}

/// Raspberry Pi Pico + SSD1306 128x64 1-bit OLED on I2C.
pub const PICO_SSD1306: Example = Example { folder: "pico-ssd1306", binary: "microtrace-pico-ssd1306", chip: &RP2040 };
/// Raspberry Pi Pico + ST7789 240x240 RGB565 on SPI (mipidsi).
pub const PICO_ST7789: Example = Example { folder: "pico-st7789", binary: "microtrace-pico-st7789", chip: &RP2040 };
/// Raspberry Pi Pico 2 + the same ST7789, in `f32` on the Cortex-M33's FPU.
pub const PICO2_ST7789: Example = Example { folder: "pico2-st7789", binary: "microtrace-pico2-st7789", chip: &RP2350 };
pub const EXAMPLES: [Example; 3] = [PICO_SSD1306, PICO_ST7789, PICO2_ST7789];

/// What an image must fit on the chip.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Chip {
    pub name: &'static str,
    /// The whole flash (on the RP2040 the QSPI flash seen at 0x1000_0000; a Pico has 2 MB).
    pub flash: Range<u64>,
    /// Where the vector table must be (the RP2040's boot ROM runs boot2 from the first 256
    /// bytes, which then jumps to the vector table after it).
    pub vector_table: u64,
    /// The second-stage boot loader's place, if the chip has one.
    pub boot2: Option<Range<u64>>,
    /// The RAM (the RP2040's 264 KB: four striped 64 KB banks and two 4 KB ones).
    pub ram: Range<u64>,
    /// The family ID its boot ROM wants in a UF2 file.
    pub uf2_family: u32,
    /// Where the boot ROM looks for the image's metadata block (the RP2350's IMAGE_DEF), if
    /// the chip wants one.
    pub image_def: Option<Range<u64>>,
    /// The rust target of its cores.
    pub rust_target: &'static str,
}

pub const RP2040: Chip = Chip {
    name: "RP2040",
    flash: 0x1000_0000..0x1000_0000 + 2 * 1024 * 1024,
    vector_table: 0x1000_0100,
    boot2: Some(0x1000_0000..0x1000_0100),
    ram: 0x2000_0000..0x2000_0000 + 264 * 1024,
    uf2_family: crate::uf2::RP2040_FAMILY,
    image_def: None,
    rust_target: "thumbv6m-none-eabi",
};

/// The RP2350 of the Pico 2, its Arm cores: no boot2 (the boot ROM sets up the flash itself),
/// the vector table at the flash's start, and an IMAGE_DEF block in the first 4 KB of flash
/// (RP2350 datasheet, 5.9). A Pico 2 has 4 MB of flash; 520 KB of SRAM.
pub const RP2350: Chip = Chip {
    name: "RP2350",
    flash: 0x1000_0000..0x1000_0000 + 4 * 1024 * 1024,
    vector_table: 0x1000_0000,
    boot2: None,
    ram: 0x2000_0000..0x2000_0000 + 520 * 1024,
    uf2_family: crate::uf2::RP2350_ARM_SECURE_FAMILY,
    image_def: Some(0x1000_0000..0x1000_0000 + 4096),
    rust_target: "thumbv8m.main-none-eabihf",
};

/// The RP2350's IMAGE_DEF for a Secure Arm executable, word by word (RP2350 datasheet, 5.9
/// "Metadata block details", and 5.9.5.1, the minimum Arm IMAGE_DEF): the block's start marker; the IMAGE_TYPE item (0x42, one
/// word) with flags 0x1021 (an executable, Secure, Arm cores, RP2350); the LAST item (0xff, one
/// word before it); the link to the next block (0: this block loops to itself); the end marker.
pub const RP2350_SECURE_ARM_IMAGE_DEF: [u32; 5] = [0xffff_ded3, 0x1021_0142, 0x0000_01ff, 0, 0xab12_3579];

/// What [`check_image`] found in an ELF.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ImageReport {
    pub entry: u64,
    pub initial_stack_pointer: u64,
    pub reset_vector: u64,
    pub text_bytes: u64,
    pub flash_bytes: u64,
    pub static_ram_bytes: u64,
    /// The end of the last byte stored in flash (code, read-only data, and `.data`'s initial values).
    pub flash_end: u64,
    /// Each required symbol (a part of a demangled name) and the size of the largest function
    /// that matched it.
    pub symbols: Vec<(String, u64)>,
}

/// Checks that `elf` is a complete image for `chip`: boot2 in its place (if the chip has one),
/// a vector table at the chip's vector-table address whose initial stack pointer is in RAM and
/// whose reset vector (a Thumb address) points into `.text`, the ELF entry that same reset
/// handler, a `.text` of at least `min_text_bytes`, every allocated section within flash or
/// RAM (and what is stored in flash, `.data`'s initial values too, within the flash), and a
/// function for every one of `symbols` (a part of a demangled name). Returns every problem
/// found, not just the first.
pub fn check_image(elf: &[u8], chip: &Chip, min_text_bytes: u64, symbols: &[&str]) -> Result<ImageReport, Vec<String>> {
    let file = object::File::parse(elf).map_err(|error| vec![format!("not an ELF file: {error}")])?;
    let mut problems = Vec::new();
    let mut report = ImageReport { entry: file.entry(), ..ImageReport::default() };

    let section = |name: &str| file.section_by_name(name);
    match (&chip.boot2, section(".boot2")) {
        (Some(range), Some(boot2)) => {
            if boot2.address() != range.start || boot2.size() != range.end - range.start {
                problems.push(format!("`.boot2` is {} bytes at {:#x}, not {} at {:#x}", boot2.size(), boot2.address(), range.end - range.start, range.start));
            }
        }
        (Some(_), None) => problems.push("no `.boot2` section (the RP2040's second-stage boot loader)".into()),
        (None, _) => {}
    }

    if let Some(range) = &chip.image_def {
        check_image_def(&file, range, &mut problems);
    }
    let text = section(".text");
    let text_range = text.as_ref().map_or(0..0, |text| text.address()..text.address() + text.size());
    report.text_bytes = text_range.end - text_range.start;
    if report.text_bytes < min_text_bytes {
        problems.push(format!("`.text` is {} bytes, less than the {min_text_bytes} a render needs", report.text_bytes));
    }

    match section(".vector_table") {
        None => problems.push(format!("no `.vector_table` section (cortex-m-rt's link.x was not used); {} expected at {:#x}", chip.name, chip.vector_table)),
        Some(vectors) => {
            if vectors.address() != chip.vector_table {
                problems.push(format!("the vector table is at {:#x}, not at {:#x}", vectors.address(), chip.vector_table));
            }
            let words: Vec<u64> = vectors
                .data()
                .unwrap_or(&[])
                .chunks_exact(4)
                .take(2)
                .map(|word| u64::from(u32::from_le_bytes([word[0], word[1], word[2], word[3]])))
                .collect();
            if let [stack_pointer, reset] = words[..] {
                report.initial_stack_pointer = stack_pointer;
                report.reset_vector = reset;
                // The stack grows down from the initial stack pointer, which may be RAM's end.
                if !(chip.ram.start < stack_pointer && stack_pointer <= chip.ram.end) {
                    problems.push(format!("the initial stack pointer {stack_pointer:#x} is not in RAM {:#x}..{:#x}", chip.ram.start, chip.ram.end));
                }
                if reset & 1 == 0 {
                    problems.push(format!("the reset vector {reset:#x} is not a Thumb address"));
                }
                if !text_range.contains(&(reset & !1)) {
                    problems.push(format!("the reset vector {reset:#x} is not in `.text` {:#x}..{:#x}", text_range.start, text_range.end));
                }
                if file.entry() & !1 != reset & !1 {
                    problems.push(format!("the ELF entry {:#x} is not the reset handler {reset:#x}", file.entry()));
                }
            } else {
                problems.push(format!("the vector table has {} bytes, not even a stack pointer and a reset vector", vectors.size()));
            }
        }
    }

    const SHF_WRITE: u64 = 0x1;
    const SHF_ALLOC: u64 = 0x2;
    let mut flash_end = chip.flash.start;
    let mut data_bytes = 0;
    for section in file.sections() {
        let SectionFlags::Elf { sh_flags } = section.flags() else { continue };
        if sh_flags & SHF_ALLOC == 0 || section.size() == 0 {
            continue;
        }
        let name = section.name().unwrap_or("?").to_owned();
        let range = section.address()..section.address() + section.size();
        let nobits = matches!(section.kind(), SectionKind::UninitializedData | SectionKind::UninitializedTls);
        if sh_flags & SHF_WRITE == 0 {
            if !(chip.flash.start <= range.start && range.end <= chip.flash.end) {
                problems.push(format!("`{name}` {:#x}..{:#x} is not within the flash", range.start, range.end));
            }
            flash_end = flash_end.max(range.end);
            report.flash_bytes += section.size();
        } else {
            if !(chip.ram.start <= range.start && range.end <= chip.ram.end) {
                problems.push(format!("`{name}` {:#x}..{:#x} is not within the RAM", range.start, range.end));
            }
            report.static_ram_bytes += section.size();
            if !nobits {
                data_bytes += section.size();
            }
        }
    }
    // `.data`'s initial values are stored after the read-only sections.
    report.flash_bytes += data_bytes;
    report.flash_end = flash_end + data_bytes;
    if report.flash_end > chip.flash.end {
        problems.push(format!("the image ends at {:#x}, past the flash's end {:#x}", report.flash_end, chip.flash.end));
    }

    let functions: Vec<(String, u64)> = file
        .symbols()
        .filter(|symbol| symbol.kind() == object::SymbolKind::Text && symbol.size() > 0)
        .filter_map(|symbol| symbol.name().ok().map(|name| (crate::elf::demangle(name), symbol.size())))
        .collect();
    for wanted in symbols {
        match functions.iter().filter(|(name, _)| name.contains(wanted)).map(|(_, size)| *size).max() {
            Some(size) => report.symbols.push(((*wanted).to_owned(), size)),
            None => problems.push(format!("no function `{wanted}` in the image")),
        }
    }

    if problems.is_empty() {
        Ok(report)
    } else {
        Err(problems)
    }
}

/// The RP2350's IMAGE_DEF: a `.start_block` section within `range` holding exactly
/// [`RP2350_SECURE_ARM_IMAGE_DEF`].
fn check_image_def(file: &object::File, range: &Range<u64>, problems: &mut Vec<String>) {
    let Some(block) = file.section_by_name(".start_block") else {
        problems.push(format!("no `.start_block` section: the RP2350's boot ROM needs an IMAGE_DEF block in {:#x}..{:#x}", range.start, range.end));
        return;
    };
    let place = block.address()..block.address() + block.size();
    if !(range.start <= place.start && place.end <= range.end) {
        problems.push(format!("the IMAGE_DEF block is at {:#x}..{:#x}, not within the first 4 KB of flash {:#x}..{:#x}", place.start, place.end, range.start, range.end));
    }
    let words: Vec<u32> = block.data().unwrap_or(&[]).chunks_exact(4).map(|word| u32::from_le_bytes([word[0], word[1], word[2], word[3]])).collect();
    if words != RP2350_SECURE_ARM_IMAGE_DEF {
        let hex: Vec<String> = words.iter().map(|word| format!("{word:#010x}")).collect();
        problems.push(format!("the IMAGE_DEF block is [{}], not a Secure Arm executable's", hex.join(", ")));
    }
}

/// Builds every example; returns their ELFs.
pub fn build_all() -> Result<Vec<PathBuf>, String> {
    EXAMPLES.iter().map(build).collect()
}

/// The UF2 file beside an example's ELF.
pub fn uf2_path(elf: &Path) -> PathBuf {
    elf.with_extension("uf2")
}

/// Builds the example in release mode and returns its ELF, with its UF2 file written beside it
/// ([`uf2_path`]: every loadable byte, in the chip's family). Installs flip-link (the examples'
/// linker) when it is missing.
pub fn build(example: &Example) -> Result<PathBuf, String> {
    let target = example.chip.rust_target;
    crate::setup::ensure_rust_target(target)?;
    crate::setup::ensure_cargo_install("flip-link")?;
    let directory = crate::firmware_dir().join("examples").join(example.folder);
    let target_dir = directory.join("target");
    let output = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .args(["build", "--release", "--quiet", "--target", target])
        .arg("--target-dir")
        .arg(&target_dir)
        .current_dir(&directory)
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("CARGO_BUILD_TARGET")
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .stdin(Stdio::null())
        .output()
        .map_err(|error| format!("cannot run cargo: {error}"))?;
    if !output.status.success() {
        return Err(format!("building the example {} failed:\n{}", example.folder, String::from_utf8_lossy(&output.stderr)));
    }
    let elf = target_dir.join(target).join("release").join(example.binary);
    let bytes = std::fs::read(&elf).map_err(|error| format!("{}: {error}", elf.display()))?;
    let uf2 = crate::uf2::from_elf(&bytes, example.chip.flash.clone(), example.chip.uf2_family).map_err(|error| format!("{}: no UF2 file: {error}", elf.display()))?;
    let path = uf2_path(&elf);
    std::fs::write(&path, uf2).map_err(|error| format!("{}: {error}", path.display()))?;
    Ok(elf)
}
