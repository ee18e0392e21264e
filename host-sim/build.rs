//! The build id both programs carry (`src/window_binary.rs`): a hash of the sources they are
//! built from (this package's and the core's, the lock file) and of the profile and target, so
//! that `microtrace view` can tell a `microtrace-view` built from other sources.

use std::collections::hash_map::DefaultHasher;
use std::fs;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};

/// Every file under `path` (or `path` itself), sorted, so the hash does not depend on the
/// order the file system lists them in.
fn files(path: &Path, found: &mut Vec<PathBuf>) {
    match fs::read_dir(path) {
        Ok(entries) => {
            for entry in entries.flatten() {
                files(&entry.path(), found);
            }
        }
        Err(_) => found.push(path.to_path_buf()),
    }
}

fn main() {
    let inputs = ["build.rs", "Cargo.toml", "src", "../core/Cargo.toml", "../core/src", "../Cargo.lock"];
    let mut found = Vec::new();
    for input in inputs {
        println!("cargo:rerun-if-changed={input}");
        files(Path::new(input), &mut found);
    }
    found.sort();
    let mut hasher = DefaultHasher::new();
    for file in &found {
        file.hash(&mut hasher);
        fs::read(file).unwrap_or_default().hash(&mut hasher);
    }
    for variable in ["PROFILE", "TARGET", "OPT_LEVEL", "DEBUG"] {
        std::env::var(variable).unwrap_or_default().hash(&mut hasher);
    }
    println!("cargo:rustc-env=MICROTRACE_BUILD_ID={:016x}", hasher.finish());
}
