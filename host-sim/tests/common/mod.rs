//! What the command-line tests share: running the binary from the repository root, a scratch
//! directory per test, and output as text.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `microtrace` with `arguments` from the repository root (so `scenes/...` resolves).
pub fn microtrace(arguments: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_microtrace"))
        .args(arguments)
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join(".."))
        .output()
        .expect("the microtrace binary runs")
}

/// An empty directory of this process for the test called `name`.
pub fn scratch(name: &str) -> PathBuf {
    let directory = std::env::temp_dir().join(format!("microtrace-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&directory);
    std::fs::create_dir_all(&directory).unwrap();
    directory
}

pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}
