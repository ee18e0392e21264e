//! Installs what the firmware tasks need when it is missing (CI machines start bare): the rust
//! target of the board, QEMU, gcc (for the instruction-count plugin) and flip-link (the
//! firmware's linker). Runs once per process.

use std::process::{Command, Stdio};
use std::sync::Mutex;

static DONE_FOR_TARGETS: Mutex<Vec<String>> = Mutex::new(Vec::new());

pub fn ensure_tools(rust_target: &str) -> Result<(), String> {
    let mut done = DONE_FOR_TARGETS.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if done.iter().any(|target| target == rust_target) {
        return Ok(());
    }
    ensure_rust_target(rust_target)?;
    ensure_cargo_install("flip-link")?;
    let mut missing = Vec::new();
    if !on_path("qemu-system-arm") {
        missing.push("qemu-system-arm");
    }
    if !on_path("gcc") {
        missing.push("gcc");
    }
    if !missing.is_empty() {
        apt_install(&missing)?;
    }
    done.push(rust_target.to_owned());
    Ok(())
}

pub fn on_path(program: &str) -> bool {
    Command::new("sh")
        .args(["-c", &format!("command -v {program}")])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|status| status.success())
}

pub fn ensure_rust_target(target: &str) -> Result<(), String> {
    let installed = Command::new("rustup")
        .args(["target", "list", "--installed"])
        .output()
        .map_err(|error| format!("cannot run rustup: {error}"))?;
    if String::from_utf8_lossy(&installed.stdout).lines().any(|line| line.trim() == target) {
        return Ok(());
    }
    eprintln!("xtask: rustup target add {target}");
    let status = Command::new("rustup")
        .args(["target", "add", target])
        .stdin(Stdio::null())
        .status()
        .map_err(|error| format!("cannot run rustup: {error}"))?;
    if !status.success() {
        return Err(format!("`rustup target add {target}` failed"));
    }
    Ok(())
}

/// `cargo install --locked PROGRAM` when `PROGRAM` is not on the PATH (the real-board examples'
/// linker, flip-link: a small crate, a few seconds to build).
pub fn ensure_cargo_install(program: &str) -> Result<(), String> {
    if on_path(program) {
        return Ok(());
    }
    eprintln!("xtask: cargo install --locked {program}");
    let status = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .args(["install", "--locked", "--quiet", program])
        .env_remove("CARGO_TARGET_DIR")
        .stdin(Stdio::null())
        .status()
        .map_err(|error| format!("cannot run cargo: {error}"))?;
    if !status.success() {
        return Err(format!("`cargo install --locked {program}` failed"));
    }
    Ok(())
}

/// `apt-get install` as root (CI is root), or through sudo otherwise.
fn apt_install(packages: &[&str]) -> Result<(), String> {
    eprintln!("xtask: installing {}", packages.join(" "));
    let is_root = Command::new("id").arg("-u").output().is_ok_and(|output| output.stdout.starts_with(b"0"));
    let prefix = if is_root { "" } else { "sudo " };
    let script = format!(
        "{prefix}apt-get update -qq && DEBIAN_FRONTEND=noninteractive {prefix}apt-get install -y -qq {}",
        packages.join(" ")
    );
    let status = Command::new("sh")
        .args(["-c", &script])
        .stdin(Stdio::null())
        .status()
        .map_err(|error| format!("cannot run apt-get: {error}"))?;
    if !status.success() {
        return Err(format!("installing {} failed; install it by hand", packages.join(" ")));
    }
    Ok(())
}

/// An LLVM tool (`llvm-nm`, `llvm-objdump`): the toolchain's (the llvm-tools component that
/// scripts/setup.sh adds), else the one on the PATH.
pub fn llvm_tool(name: &str) -> std::path::PathBuf {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let ask = |arguments: &[&str]| {
        Command::new(&rustc).args(arguments).output().ok().map(|output| String::from_utf8_lossy(&output.stdout).into_owned())
    };
    let sysroot = ask(&["--print", "sysroot"]).map(|text| text.trim().to_owned());
    let host = ask(&["-vV"]).and_then(|text| text.lines().find_map(|line| line.strip_prefix("host: ").map(str::to_owned)));
    if let (Some(sysroot), Some(host)) = (sysroot, host) {
        let tool = std::path::PathBuf::from(sysroot).join("lib/rustlib").join(host).join("bin").join(name);
        if tool.is_file() {
            return tool;
        }
    }
    std::path::PathBuf::from(name)
}
