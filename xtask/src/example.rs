//! `cargo xtask firmware-example`: builds (does not run) the real-board example,
//! firmware/examples/pico-ssd1306 (Raspberry Pi Pico + SSD1306), a cargo workspace of its own.

use std::path::PathBuf;
use std::process::{Command, Stdio};

pub const EXAMPLE_TARGET: &str = "thumbv6m-none-eabi";

/// Builds the example in release mode and returns its ELF.
pub fn build() -> Result<PathBuf, String> {
    crate::setup::ensure_rust_target(EXAMPLE_TARGET)?;
    let directory = crate::firmware_dir().join("examples/pico-ssd1306");
    let target_dir = directory.join("target");
    let output = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .args(["build", "--release", "--quiet", "--target", EXAMPLE_TARGET])
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
        return Err(format!("building the Pico example failed:\n{}", String::from_utf8_lossy(&output.stderr)));
    }
    Ok(target_dir.join(EXAMPLE_TARGET).join("release/microtrace-pico-ssd1306"))
}
