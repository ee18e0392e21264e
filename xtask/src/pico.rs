//! The Raspberry Pi Pico examples' images run in the rp2040js emulator (Node.js, the harness
//! `tests/rp2040/run-pico.mjs`): each example's UF2 file boots from the RP2040's boot ROM, and
//! the harness models the example's display on its bus and hands back what the display holds,
//! with the emulated Cortex-M0+ cycles to the last display byte. The tests compare the picture
//! with the host's render (`tests/tests/pico_emulated.rs`); the firmware report quotes the
//! cycles (`crate::report`).

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::example::{self, Example};

/// How an example is emulated: the display model, the file the harness writes its memory to,
/// and the cycles after which the run counts as hung.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Emulation {
    /// `ssd1306` (I2C0 at 0x3C: the 1024-byte page memory) or `st7789` (SPI0 with DC:
    /// 240x240 RGB565, each pixel big-endian).
    pub display: &'static str,
    pub output: &'static str,
    pub max_cycles: u64,
    /// The display's width and height in pixels.
    pub size: (u64, u64),
}

/// The emulation of an example, or `None` for one the harness has no display model for.
pub fn emulation(example: &Example) -> Option<Emulation> {
    match example.folder {
        "pico-ssd1306" => Some(Emulation { display: "ssd1306", output: ".pages.bin", max_cycles: 400_000_000, size: (128, 64) }),
        "pico-st7789" => Some(Emulation { display: "st7789", output: ".rgb565", max_cycles: 3_000_000_000, size: (240, 240) }),
        _ => None,
    }
}

/// What an emulated run left.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EmulatedRun {
    /// The display's memory as the harness wrote it.
    pub display: Vec<u8>,
    /// Emulated Cortex-M0+ cycles from reset to the last display byte.
    pub cycles: u64,
    /// The cycle at which the core first entered the example's `render` (the harness's
    /// `render_entered` milestone): what comes before is booting, the clocks, the display's
    /// set-up, parsing and preparing the scene.
    pub render_entered: Option<u64>,
    /// Instructions executed from reset to the last display byte, and to the entry into
    /// `render` (what QEMU's plugin counts for the firmware, so the two compare).
    pub instructions: Option<u64>,
    pub render_entered_instructions: Option<u64>,
    /// The harness's JSON summary.
    pub summary: String,
}

/// The RP2040's boot ROM, beside the repository (`../shared/rp2040/`; its README says where it
/// comes from). It is not part of the project.
pub fn boot_rom() -> PathBuf {
    crate::repository_root().join("../shared/rp2040/bootrom-b1.bin")
}

/// Builds `example` (with its UF2 file), boots the UF2 file in rp2040js and returns what its
/// display received; the harness's files go to `out`. Fails naming what is missing (the boot
/// ROM, rp2040js, Node.js) or what the harness saw go wrong (a fault, a run past its cycle
/// limit, nothing drawn).
pub fn run(example: &Example, out: &Path) -> Result<EmulatedRun, String> {
    let emulation = emulation(example).ok_or_else(|| format!("{}: no display model for it in the harness", example.folder))?;
    let rom = boot_rom();
    if !rom.is_file() {
        return Err(format!(
            "{}: missing. The RP2040's boot ROM (revision B1, from Raspberry Pi's pico-bootrom, as rp2040js's demo ships it) must be beside the repository; see ../shared/rp2040/README.md",
            rom.display()
        ));
    }
    let harness = crate::repository_root().join("tests/rp2040");
    if !harness.join("node_modules/rp2040js/package.json").is_file() {
        return Err(format!("{}: rp2040js is not installed; run scripts/setup.sh (npm ci there)", harness.display()));
    }
    let elf = example::build(example)?;
    std::fs::create_dir_all(out).map_err(|error| format!("{}: {error}", out.display()))?;
    let prefix = out.join(emulation.display);
    let result = Command::new("node")
        .arg(harness.join("run-pico.mjs"))
        .arg(emulation.display)
        .arg(&elf)
        .arg(&rom)
        .arg(&prefix)
        .arg("--uf2")
        .arg(example::uf2_path(&elf))
        .args(["--max-cycles", &emulation.max_cycles.to_string()])
        .output()
        .map_err(|error| format!("node (Node.js, which scripts/setup.sh installs): {error}"))?;
    let summary = String::from_utf8_lossy(&result.stdout).into_owned();
    if !result.status.success() {
        return Err(format!("{} in rp2040js failed ({}):\n{}\n{summary}", example.folder, result.status, String::from_utf8_lossy(&result.stderr)));
    }
    if number_in(&summary, "blocks").is_none_or(|blocks| blocks == 0) {
        return Err(format!("the harness did not load the UF2 file:\n{summary}"));
    }
    let cycles = number_in(&summary, "cycles_to_last_display_byte").ok_or_else(|| format!("no cycle count in:\n{summary}"))?;
    let path = PathBuf::from(format!("{}{}", prefix.display(), emulation.output));
    let display = std::fs::read(&path).map_err(|error| format!("{}: {error}", path.display()))?;
    let render_entered = number_in(&summary, "render_entered");
    let instructions = number_in(&summary, "instructions_to_last_display_byte");
    let render_entered_instructions = number_in(&summary, "instructions_to_render_entered");
    Ok(EmulatedRun { display, cycles, render_entered, instructions, render_entered_instructions, summary })
}

/// The whole number after `"key":` in the harness's JSON summary.
pub fn number_in(summary: &str, key: &str) -> Option<u64> {
    let after = summary.split(&format!("\"{key}\":")).nth(1)?;
    after.trim_start().split(|c: char| !c.is_ascii_digit()).next()?.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_read_from_the_summary() {
        let summary = "{\n  \"ok\": true,\n  \"cycles_to_last_display_byte\": 69983684,\n  \"milestones_cycles\": {\"render_entered\": 10272351},\n  \"loaded\": [{\"uf2\": \"x.uf2\", \"blocks\": 394}]\n}";
        assert_eq!(number_in(summary, "cycles_to_last_display_byte"), Some(69_983_684));
        assert_eq!(number_in(summary, "blocks"), Some(394));
        assert_eq!(number_in(summary, "render_entered"), Some(10_272_351));
        assert_eq!(number_in(summary, "ok"), None);
        assert_eq!(number_in(summary, "missing"), None);
    }
}
