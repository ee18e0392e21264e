//! A board of your own (docs/your-board.md): `firmware/examples/your-board`, a crate of its own
//! that depends on `microtrace` by path as a user's would, bakes snooker in its `build.rs`
//! (`microtrace::bake`, at most ten lines), includes the file and prepares it with one call.
//! Built for the Cortex-M4F and run on QEMU's mps2-an386, its picture (`framebuffer.bin`, sent
//! by semihosting) must equal the host's render byte for byte.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("the workspace").to_path_buf()
}

fn example() -> PathBuf {
    workspace().join("firmware/examples/your-board")
}

/// The build script a user copies: its lines of code (not comments or blank lines).
#[test]
fn the_bake_takes_at_most_ten_lines_of_build_script() {
    let text = std::fs::read_to_string(example().join("build.rs")).unwrap();
    let code = text.lines().map(str::trim).filter(|line| !line.is_empty() && !line.starts_with("//")).count();
    assert!(code <= 10, "firmware/examples/your-board/build.rs has {code} lines of code");
    assert!(text.contains("microtrace::bake::bake("), "the build script does not call the bake");
}

#[test]
fn your_board_runs_the_baked_scene_as_the_host_renders_it() {
    xtask::setup::ensure_tools("thumbv7em-none-eabihf").unwrap();
    let directory = example();
    let target_dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("your-board-target");
    let output = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .args(["build", "--release", "--quiet"])
        .arg("--target-dir")
        .arg(&target_dir)
        .current_dir(&directory)
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("CARGO_BUILD_TARGET")
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    assert!(output.status.success(), "your-board does not build:\n{}", String::from_utf8_lossy(&output.stderr));
    let elf = target_dir.join("thumbv7em-none-eabihf/release/microtrace-your-board");
    let run = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("your-board-run");
    let _ = std::fs::remove_dir_all(&run);
    std::fs::create_dir_all(&run).unwrap();
    let mut qemu = Command::new("qemu-system-arm")
        .args(["-machine", "mps2-an386", "-nographic", "-monitor", "none", "-serial", "none", "-semihosting-config", "enable=on,target=native", "-kernel"])
        .arg(&elf)
        .current_dir(&run)
        .stdin(Stdio::null())
        .spawn()
        .unwrap();
    let started = Instant::now();
    let status = loop {
        if let Some(status) = qemu.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > Duration::from_secs(120) {
            let _ = qemu.kill();
            panic!("your-board ran for more than 120 s under QEMU");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    assert!(status.success(), "your-board failed under QEMU ({status})");
    let picture = std::fs::read(run.join("framebuffer.bin")).expect("your-board wrote no framebuffer.bin");
    let host = xtask::host_render::render(&workspace().join("scenes/snooker.mts"), "f32", "scene").unwrap();
    assert_eq!(picture.len(), host.len(), "the picture is not 128x64");
    let differing = picture.iter().zip(&host).filter(|(a, b)| a != b).count();
    assert_eq!(differing, 0, "{differing} of the board's pixels differ from the host's render");
}
