//! `microtrace view` runs in a program of its own, `microtrace-view`, installed beside
//! `microtrace`: the simulator window needs SDL2, and a program linked with SDL2 loads it and
//! the 50 libraries behind it (X11, Wayland, PulseAudio, ALSA, D-Bus, ...) at every start, the
//! SDL-free `render` too. Measured (docs/desktop-speed.md), that start-up was several
//! milliseconds of each `microtrace render`; `microtrace` itself now links libc, libm and
//! libgcc_s only, and `microtrace view ARGS` replaces itself with `microtrace-view ARGS`.
//!
//! Both programs carry the build id of the sources they were built from (`build.rs`), so a
//! `microtrace-view` left over from other sources is refused with a message rather than run.

use std::ffi::OsString;
use std::path::PathBuf;

use anyhow::{bail, Context};

/// The environment variable through which `microtrace` tells `microtrace-view` its build id.
pub const PARENT_BUILD_ID: &str = "MICROTRACE_PARENT_BUILD_ID";

/// The window program's file name.
pub fn window_program_name() -> String {
    format!("microtrace-view{}", std::env::consts::EXE_SUFFIX)
}

/// Where the window program is: beside the running `microtrace`.
fn window_program() -> anyhow::Result<PathBuf> {
    let this = std::env::current_exe().context("cannot tell where microtrace is, to find microtrace-view beside it")?;
    let program = this.with_file_name(window_program_name());
    if !program.is_file() {
        bail!(
            "the simulator window is the program microtrace-view, which is not beside {} \
             (build both programs: cargo build --release -p microtrace-sim; or run the window \
             directly: cargo run --release --bin microtrace-view -- SCENE.mts)",
            this.display()
        );
    }
    Ok(program)
}

/// Runs `microtrace-view` with `args` (what followed `view` on the command line) in place of
/// this process (on Unix; elsewhere as a child whose exit status this process then takes).
/// `build_id` is this program's, which the window program checks against its own.
pub fn run_view(build_id: &str, args: impl IntoIterator<Item = OsString>) -> anyhow::Result<()> {
    let program = window_program()?;
    let mut command = std::process::Command::new(&program);
    command.args(args).env(PARENT_BUILD_ID, build_id);
    #[cfg(unix)]
    {
        use std::os::unix::process::CommandExt;
        let error = command.exec();
        Err(error).with_context(|| format!("cannot run {}", program.display()))
    }
    #[cfg(not(unix))]
    {
        let status = command.status().with_context(|| format!("cannot run {}", program.display()))?;
        std::process::exit(status.code().unwrap_or(1));
    }
}

/// In `microtrace-view`: refuses to run for a `microtrace` built from other sources (the
/// window program would show another tracer's images). Run directly, without `microtrace`,
/// there is nothing to check.
pub fn check_parent_build(build_id: &str) -> anyhow::Result<()> {
    match std::env::var_os(PARENT_BUILD_ID) {
        Some(parent) if parent != build_id => bail!(
            "microtrace-view was built from other sources than the microtrace that started it \
             (build ids {build_id} and {}): rebuild both, e.g. cargo build --release -p microtrace-sim",
            parent.to_string_lossy()
        ),
        _ => Ok(()),
    }
}
