//! `microtrace render` under stress (issue 12, item 5): the largest size it accepts, a scene
//! file cut short as if still being written, an output directory that is missing, not a
//! directory or not writable, and Ctrl-C (SIGINT) while rendering and while writing. Each ends
//! with a clear message and a non-zero exit, and never leaves a partial or temporary file.

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

mod common;

use common::{microtrace, scratch, text};

/// The files in `directory`, sorted.
fn listing(directory: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        std::fs::read_dir(directory).unwrap().map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
}

fn temporaries(directory: &Path) -> Vec<String> {
    listing(directory).into_iter().filter(|name| name.ends_with(".tmp")).collect()
}

/// A PNG's width and height from its header.
fn png_size(path: &Path) -> (u32, u32) {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{} is not a PNG", path.display());
    let word = |at: usize| u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap());
    (word(16), word(20))
}

fn path_text(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// A scene of no objects: the render is quick, the image all background.
const EMPTY_SCENE: &str = "viewport 0 9 0 9\nbackground 7\n";

#[test]
fn the_largest_size_renders_and_anything_larger_is_refused_clearly() {
    let directory = scratch("stress-size");
    let scene = directory.join("empty.mts");
    std::fs::write(&scene, EMPTY_SCENE).unwrap();
    let image = directory.join("big.png");
    let output = microtrace(&["render", path_text(&scene), "--size", "8192x8192", "--out", path_text(&image)]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    assert_eq!(png_size(&image), (8192, 8192));
    std::fs::remove_file(&image).unwrap();

    let output = microtrace(&["render", path_text(&scene), "--size", "8193x8192", "--out", path_text(&image)]);
    assert!(!output.status.success());
    assert!(text(&output.stderr).contains("each side must be a whole number from 1 to 8192"), "{}", text(&output.stderr));

    // A scene's own viewport can be larger than --size allows: refused before any work.
    let huge = directory.join("huge.mts");
    std::fs::write(&huge, "viewport 0 32767 0 32767\n").unwrap();
    let output = microtrace(&["render", path_text(&huge), "--out", path_text(&image)]);
    assert_eq!(output.status.code(), Some(1));
    assert_eq!(
        text(&output.stderr),
        format!("microtrace: cannot render {}: the viewport is 32768x32768: too large to render in memory\n", huge.display())
    );
    assert_eq!(listing(&directory), ["empty.mts", "huge.mts"], "nothing written");
}

#[test]
fn a_scene_cut_short_while_being_written_is_an_error_naming_file_and_line() {
    let directory = scratch("stress-truncated");
    let snooker = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/snooker.mts")).unwrap();
    let image = directory.join("image.png");
    std::fs::write(&image, b"an earlier image").unwrap();
    let scene = directory.join("snooker.mts");
    let scale = snooker.find("\n  scale ").unwrap() + "\n  scale ".len();
    let keyword = snooker.find("\nsphere").unwrap() + "\nsph".len();
    for (cut, reason) in [(scale + 2, "`scale` takes 3 arguments"), (keyword, "unknown keyword `sph`")] {
        std::fs::write(&scene, &snooker[..cut]).unwrap();
        let line = snooker[..cut].matches('\n').count() + 1;
        let output = microtrace(&["render", path_text(&scene), "--size", "33x30", "--out", path_text(&image)]);
        assert_eq!(output.status.code(), Some(1), "cut at {cut}");
        let expected = format!("microtrace: {}:line {line}: {reason}", scene.display());
        assert!(text(&output.stderr).starts_with(&expected), "cut at {cut}: {}\nexpected {expected}", text(&output.stderr));
        assert_eq!(std::fs::read(&image).unwrap(), b"an earlier image", "the existing file of that name is untouched");
        assert_eq!(listing(&directory), ["image.png", "snooker.mts"]);
    }
    // Cut between two statements, the scene is a valid, smaller scene, and renders.
    let whole_line = snooker[..scale].rfind('\n').unwrap() + 1;
    std::fs::write(&scene, &snooker[..whole_line]).unwrap();
    let output = microtrace(&["render", path_text(&scene), "--size", "33x30", "--out", path_text(&image)]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    assert_eq!(png_size(&image), (33, 30));
}

#[test]
fn an_output_directory_missing_not_a_directory_or_unwritable_is_a_clear_error_leaving_nothing() {
    let directory = scratch("stress-output");
    let scene = "scenes/snooker.mts";
    let check = |out: &Path, option: &str, expected: &str| {
        let output = microtrace(&["render", scene, "--size", "20x20", option, path_text(out)]);
        assert_eq!(output.status.code(), Some(1), "{}", out.display());
        let stderr = text(&output.stderr);
        let prefix = format!("microtrace: cannot write {}: ", out.display());
        assert!(stderr.starts_with(&prefix) && stderr.contains(expected), "{stderr}\nexpected {prefix}...{expected}");
        assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
    };
    check(&directory.join("missing").join("image.png"), "--out", "No such file or directory");
    check(&directory.join("missing").join("image.pga"), "--pga", "No such file or directory");
    let file = directory.join("a-file");
    std::fs::write(&file, b"not a directory").unwrap();
    check(&file.join("image.png"), "--out", "Not a directory");
    let existing_directory = directory.join("taken.png");
    std::fs::create_dir(&existing_directory).unwrap();
    check(&existing_directory, "--out", "Is a directory");
    assert_eq!(listing(&directory), ["a-file", "taken.png"], "no temporary file left");
    assert!(listing(&existing_directory).is_empty());

    // A directory without write permission. Root writes there regardless, so when the test runs
    // as root a directory of a read-only file system stands in (/proc).
    use std::os::unix::fs::PermissionsExt;
    let locked = directory.join("locked");
    std::fs::create_dir(&locked).unwrap();
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o555)).unwrap();
    let root = std::fs::write(locked.join("probe"), b"").is_ok();
    if root {
        std::fs::remove_file(locked.join("probe")).unwrap();
        let output = microtrace(&["render", scene, "--size", "20x20", "--out", "/proc/microtrace-image.png"]);
        assert_eq!(output.status.code(), Some(1));
        assert!(text(&output.stderr).starts_with("microtrace: cannot write /proc/microtrace-image.png: "), "{}", text(&output.stderr));
    } else {
        check(&locked.join("image.png"), "--out", "Permission denied");
    }
    assert!(listing(&locked).is_empty());
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o755)).unwrap();
}

fn spawn(arguments: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_microtrace"))
        .args(arguments)
        .current_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join(".."))
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

fn interrupt(child: &Child) {
    let status = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap();
    assert!(status.success());
}

#[test]
fn ctrl_c_while_rendering_stops_with_a_message_and_no_file() {
    let directory = scratch("stress-sigint-render");
    let image = directory.join("image.png");
    let pga = directory.join("image.pga");
    // Seconds of work on one thread: the signal lands in the middle of the render.
    let child = spawn(&["render", "scenes/lattice.mts", "--size", "6000x6000", "--threads", "1", "--out", path_text(&image), "--pga", path_text(&pga)]);
    std::thread::sleep(Duration::from_millis(800));
    interrupt(&child);
    let output = child.wait_with_output().unwrap();
    assert_eq!(output.status.code(), Some(130), "{}", text(&output.stderr));
    assert!(text(&output.stderr).contains(microtrace_sim::files::INTERRUPTED), "{}", text(&output.stderr));
    assert!(listing(&directory).is_empty(), "left {:?}", listing(&directory));
}

#[test]
fn ctrl_c_while_writing_leaves_no_temporary_and_no_partial_file() {
    let directory = scratch("stress-sigint-write");
    let scene = directory.join("empty.mts");
    std::fs::write(&scene, EMPTY_SCENE).unwrap();
    let image = directory.join("image.png");
    // A quick render and a 200 MB PNG to write: wait for its temporary file, then interrupt.
    let child = spawn(&["render", path_text(&scene), "--size", "8192x8192", "--out", path_text(&image)]);
    let started = Instant::now();
    let mut seen: Vec<String> = Vec::new();
    while seen.is_empty() && started.elapsed() < Duration::from_secs(120) {
        seen = temporaries(&directory);
        std::thread::sleep(Duration::from_millis(2));
    }
    assert!(!seen.is_empty(), "no temporary file appeared");
    interrupt(&child);
    let output = child.wait_with_output().unwrap();
    eprintln!("interrupted while writing {seen:?}: exit {:?}", output.status.code());
    assert!(temporaries(&directory).is_empty(), "the temporary file {seen:?} is left");
    match output.status.code() {
        Some(130) => {
            assert!(text(&output.stderr).contains(microtrace_sim::files::INTERRUPTED), "{}", text(&output.stderr));
            assert!(!image.exists(), "an interrupted write left {}", image.display());
        }
        // The write finished before the signal landed: then the file is whole.
        Some(0) => assert_eq!(png_size(&image), (8192, 8192)),
        other => panic!("exit {other:?}: {}", text(&output.stderr)),
    }
}
