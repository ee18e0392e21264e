//! Project tasks, as a library so that the integration tests can drive them too:
//! - [`firmware::run`]: build the firmware for a scene, run it under QEMU, collect
//!   `framebuffer.bin`, `oled.png` and `report.json` (`cargo xtask firmware`);
//! - [`example::build`]: build a real-board example (`cargo xtask firmware-example`), and
//!   [`example::check_image`], what the tests check in its ELF;
//! - [`report::run`]: every thesis scene, number type and board, into docs/firmware-report.md's table and
//!   `docs/firmware-report.json` (`cargo xtask firmware-report`); [`spd_report::run`], Haines'
//!   SPD scenes on the Cortex-M4F into `docs/spd-firmware.md` (`--spd`).

pub mod budget;
pub mod elf;
pub mod example;
pub mod firmware;
pub mod host_render;
pub mod oled;
pub mod pico;
pub mod qemu;
pub mod report;
pub mod setup;
pub mod spd_report;
pub mod uf2;

use std::path::{Path, PathBuf};

/// The repository root (xtask lives one level below it).
pub fn repository_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("xtask has a parent directory").to_path_buf()
}

/// The firmware's own cargo workspace.
pub fn firmware_dir() -> PathBuf {
    repository_root().join("firmware")
}
