//! The simulator window of `microtrace view`, tested for real: under an X server (Xvfb started
//! here if DISPLAY is unset), open the window on a thesis scene, let it render, save the
//! window's contents with the simulator's own output image (`--screenshot`), and compare the
//! image area with the headless `microtrace render` of the same scene pixel for pixel.
//!
//! Needs (Debian): libsdl2-dev (build), xvfb (X server). Without a display and without Xvfb the
//! test fails under CI (CI=true) and is skipped locally.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Duration;

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("workspace root").to_path_buf()
}

/// Builds the `microtrace` binary and returns its path.
fn microtrace_binary() -> PathBuf {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let status = Command::new(cargo)
        .args(["build", "-q", "-p", "microtrace-sim", "--bin", "microtrace"])
        .current_dir(workspace())
        .status()
        .expect("run cargo build");
    assert!(status.success(), "cargo build -p microtrace-sim failed");
    let target = std::env::var_os("CARGO_TARGET_DIR").map(PathBuf::from).unwrap_or_else(|| workspace().join("target"));
    let target = if target.is_absolute() { target } else { workspace().join(target) };
    target.join("debug").join("microtrace")
}

struct Xvfb(Child);

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// A display to open the window on: `DISPLAY` if set, else a private Xvfb.
/// A display to test on; without one the test is skipped with a message, except in CI
/// (`CI=true`), where that is a failure.
fn display_or_skip() -> Option<(String, Option<Xvfb>)> {
    let found = display();
    if found.is_none() {
        let message = "no X display: set DISPLAY or install Xvfb (Debian: xvfb) to test the simulator window";
        if std::env::var("CI").is_ok_and(|v| v == "true" || v == "1") {
            panic!("{message}");
        }
        eprintln!("skipped: {message}");
    }
    found
}

fn display() -> Option<(String, Option<Xvfb>)> {
    if let Ok(display) = std::env::var("DISPLAY") {
        if !display.is_empty() {
            return Some((display, None));
        }
    }
    // One server per test (tests run in parallel threads of one process).
    static STARTED: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);
    let number = 100 + (std::process::id() % 100) * 4 + STARTED.fetch_add(1, std::sync::atomic::Ordering::Relaxed) % 4;
    let child = Command::new("Xvfb")
        .args([format!(":{number}"), "-screen".into(), "0".into(), "1024x768x24".into(), "-nolisten".into(), "tcp".into()])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let xvfb = Xvfb(child);
    // Wait for the server's socket.
    let socket = PathBuf::from(format!("/tmp/.X11-unix/X{number}"));
    for _ in 0..100 {
        if socket.exists() {
            return Some((format!(":{number}"), Some(xvfb)));
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    None
}

fn read_png(path: &Path) -> (u32, u32, Vec<[u8; 3]>) {
    let mut decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).expect("open png")));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().expect("png header");
    let mut buffer = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buffer).expect("png data");
    let channels = info.color_type.samples();
    let pixels = buffer[..info.buffer_size()]
        .chunks(channels)
        .map(|c| if channels >= 3 { [c[0], c[1], c[2]] } else { [c[0], c[0], c[0]] })
        .collect();
    (info.width, info.height, pixels)
}

fn check_scene(binary: &Path, display: &str, scene: &str, extra: &[&str]) {
    let dir = std::env::temp_dir().join(format!("microtrace-view-{}-{scene}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene_path = workspace().join("scenes").join(format!("{scene}.mts"));
    let reference = dir.join("render.png");
    let ((window_width, window_height, window), stderr) = screenshot_and_stderr(binary, display, scene, extra);
    assert!(stderr.contains("rays traced") && stderr.contains("trace"), "statistics not printed: {stderr}");
    let status = Command::new(binary)
        .arg("render")
        .arg(&scene_path)
        .args(["--size", "132x120", "--out"])
        .arg(&reference)
        .args(extra)
        .status()
        .expect("run microtrace render");
    assert!(status.success());
    let (width, height, expected) = read_png(&reference);
    assert!(window_width > width && window_height >= height, "window {window_width}x{window_height} smaller than the image");
    let mut differing = 0;
    for y in 0..height {
        for x in 0..width {
            if window[(y * window_width + x) as usize] != expected[(y * width + x) as usize] {
                differing += 1;
            }
        }
    }
    assert_eq!(differing, 0, "{scene} {extra:?}: {differing} pixels of the window's image area differ from `render` ({})", dir.display());
    // The panel is drawn: something lit to the right of the image.
    let panel_lit = (0..window_height).any(|y| (width + 8..window_width).any(|x| window[(y * window_width + x) as usize] != [0, 0, 0]));
    assert!(panel_lit, "the panel is empty");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn window_shows_the_same_image_as_render() {
    let Some((display, _xvfb)) = display_or_skip() else { return };
    let binary = microtrace_binary();
    check_scene(&binary, &display, "snooker", &[]);
    check_scene(&binary, &display, "lattice", &["--mode", "rgb"]);
    check_scene(&binary, &display, "snooker", &["--number", "f32", "--opt", "none", "--dither", "on"]);
}

/// `view --progressive` (coarse to fine, straight into the window) ends with the same window
/// image as the plain `view`, and reports each pass's rays in the panel's statistics on stderr.
#[test]
fn progressive_view_ends_with_the_same_image() {
    let Some((display, _xvfb)) = display_or_skip() else { return };
    let binary = microtrace_binary();
    for scene in ["snooker", "lattice"] {
        let ((width, height, plain), _) = screenshot_and_stderr(&binary, &display, scene, &[]);
        let ((progressive_width, _, progressive), stderr) = screenshot_and_stderr(&binary, &display, scene, &["--progressive"]);
        assert_eq!(width, progressive_width);
        let image_area = |window: &[[u8; 3]]| (0..120).flat_map(|y| (0..132).map(move |x| (y * width + x) as usize)).map(|i| window[i]).collect::<Vec<_>>();
        assert!(image_area(&plain) == image_area(&progressive), "{scene}: the progressive view's image differs");
        assert!(height >= 120 && plain != progressive, "{scene}: the panel should say progressive");
        assert!(stderr.contains("pass 1 (8x8)") && stderr.contains("pass 4 (1x1)"), "{stderr}");
    }
}

/// Each display preview (`--display oled|ssd1306|rgb565`, which `L` cycles) shows, pixel for
/// pixel, the core's image of the scene fitted to that display through the firmware's mapping:
/// the look-up table's grey (`grey_level`) on the 16-grey OLED, that grey through the 4x4
/// ordered dither (`dither_lights`) on the 1-bit SSD1306, the look-up table's colour in RGB565
/// (`lut_colour::<Rgb565>`) on the colour panel.
#[test]
fn each_display_preview_shows_the_core_image_through_its_mapping() {
    use embedded_graphics::pixelcolor::{GrayColor, Rgb565, Rgb888, RgbColor};
    use embedded_graphics::prelude::Point;
    use microtrace::pixel::{dither_lights, grey_level, lut_colour, FrameBuffer};
    let Some((display, _xvfb)) = display_or_skip() else { return };
    let binary = microtrace_binary();
    for scene in ["snooker", "lattice"] {
        let text = std::fs::read(workspace().join("scenes").join(format!("{scene}.mts"))).unwrap();
        let mut description = microtrace::parser::parse::<64>(&text).unwrap();
        description.fit_to_size(132, 120);
        for (kind, width, height, zoom) in [("oled", 128u16, 64u16, 2u32), ("ssd1306", 128, 64, 2), ("rgb565", 240, 240, 1)] {
            let mut fitted = description.clone();
            fitted.fit_to_size(width, height);
            let prepared = microtrace::scene::Scene::<f64, 64>::prepare(&fitted).unwrap();
            let mut indices = vec![0u8; usize::from(width) * usize::from(height)];
            microtrace::render::render_pga(&prepared, &mut FrameBuffer::new(&mut indices, width, height).unwrap(), &mut microtrace::render::Statistics::default());
            let palette = &fitted.palette;
            let expected: Vec<[u8; 3]> = indices
                .iter()
                .enumerate()
                .map(|(i, index)| {
                    let point = Point::new((i % usize::from(width)) as i32, (i / usize::from(width)) as i32);
                    let grey = grey_level(palette, *index).luma();
                    match kind {
                        "oled" => [grey * 17; 3],
                        "ssd1306" => if dither_lights(grey, point) { [255; 3] } else { [0; 3] },
                        _ => {
                            let colour = Rgb888::from(lut_colour::<Rgb565>(palette, *index));
                            [colour.r(), colour.g(), colour.b()]
                        }
                    }
                })
                .collect();
            let distinct: std::collections::BTreeSet<[u8; 3]> = expected.iter().copied().collect();
            assert!(distinct.len() >= 2, "{scene} {kind}: the expected preview is blank");
            let (window_width, window_height, window) = screenshot(&binary, &display, scene, &["--display", kind]);
            // The preview is at the panel's top left, inside a one-pixel frame: the panel starts
            // 8 pixels right of the 132-pixel image, 4 down.
            let origin = (132 + 8 + 1, 4 + 1);
            assert!(origin.0 + u32::from(width) * zoom <= window_width && origin.1 + u32::from(height) * zoom <= window_height);
            let mut differing = 0;
            for y in 0..u32::from(height) * zoom {
                for x in 0..u32::from(width) * zoom {
                    let shown = window[((origin.1 + y) * window_width + origin.0 + x) as usize];
                    if shown != expected[((y / zoom) * u32::from(width) + x / zoom) as usize] {
                        differing += 1;
                    }
                }
            }
            assert_eq!(differing, 0, "{scene} {kind}: {differing} window pixels of the preview differ from the core's image through the mapping");
        }
    }
}

/// Runs `microtrace view SCENE --size 132x120 --screenshot` with `extra` and returns the
/// screenshot.
fn screenshot(binary: &Path, display: &str, scene: &str, extra: &[&str]) -> (u32, u32, Vec<[u8; 3]>) {
    screenshot_and_stderr(binary, display, scene, extra).0
}

/// [`screenshot`], with what `view` printed on stderr.
fn screenshot_and_stderr(binary: &Path, display: &str, scene: &str, extra: &[&str]) -> ((u32, u32, Vec<[u8; 3]>), String) {
    // One directory per call: tests run in parallel and may take the same screenshot.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("microtrace-view-{}-shot-{call}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let shot = dir.join("window.png");
    let output = Command::new(binary)
        .arg("view")
        .arg(workspace().join("scenes").join(format!("{scene}.mts")))
        .args(["--size", "132x120", "--screenshot"])
        .arg(&shot)
        .args(extra)
        .env("DISPLAY", display)
        .output()
        .expect("run microtrace view");
    assert!(output.status.success(), "microtrace view failed: {}", String::from_utf8_lossy(&output.stderr));
    let image = read_png(&shot);
    let _ = std::fs::remove_dir_all(&dir);
    (image, String::from_utf8_lossy(&output.stderr).into_owned())
}

/// The overlay changes the image only by outlines (extents in bright object colours, grid
/// cells in grey) and adds the plan view and depth ranges beside the panel, with a distinct
/// colour for each of snooker's 21 balls. The Pixelbuffer fill (`--fill`) tints every pixel
/// that shows a ball and leaves some of the cloth alone.
fn check_overlay_and_fill(binary: &Path, display: &str) {
    let (width, height) = (132u32, 120u32);
    let (window_width, window_height, plain) = screenshot(binary, display, "snooker", &[]);
    let (overlay_width, overlay_height, overlay) = screenshot(binary, display, "snooker", &["--overlay"]);
    assert_eq!((window_width, window_height), (overlay_width, overlay_height));
    let at = |x: u32, y: u32| (y * window_width + x) as usize;
    let image = |x: u32, y: u32| x < width && y < height;
    let mut image_changed = 0;
    let mut beside = std::collections::BTreeSet::new();
    for y in 0..window_height {
        for x in 0..window_width {
            let (before, after) = (plain[at(x, y)], overlay[at(x, y)]);
            if before == after {
                continue;
            }
            if image(x, y) {
                image_changed += 1;
                // An outline: grey grid or a saturated object colour, never a shade of the image.
                let grey = after == [160, 160, 160];
                let bright = after.iter().max() == Some(&255);
                assert!(grey || bright, "overlay pixel ({x}, {y}) is {after:?}, not an outline colour");
            } else {
                beside.insert(after);
            }
        }
    }
    assert!(image_changed > 200, "the overlay drew only {image_changed} pixels on the image");
    let saturated = beside.iter().filter(|c| c.iter().max() == Some(&255) && c.iter().min() < Some(&100)).count();
    assert!(saturated >= 21, "beside the panel, {saturated} object colours for 21 balls: the plan view is missing");

    let (_, _, filled) = screenshot(binary, display, "snooker", &["--fill"]);
    let background = plain[at(0, 0)];
    let (mut tinted, mut untouched) = (0, 0);
    for y in 0..height {
        for x in 0..width {
            let (before, after) = (plain[at(x, y)], filled[at(x, y)]);
            if before != background {
                assert_ne!(before, after, "ball pixel ({x}, {y}) not tinted by the fill");
            }
            if before == after { untouched += 1 } else { tinted += 1 }
        }
    }
    assert!(tinted > 0 && untouched > 0, "fill tinted {tinted} pixels, left {untouched}");
}

#[test]
fn overlay_draws_extents_grid_and_plan_view_and_fill_tints_the_filled_pixels() {
    let Some((display, _xvfb)) = display_or_skip() else { return };
    let binary = microtrace_binary();
    check_overlay_and_fill(&binary, &display);
}

#[test]
fn no_display_points_at_render() {
    let binary = microtrace_binary();
    let scene = workspace().join("scenes").join("snooker.mts");
    let output = Command::new(&binary).arg("view").arg(&scene).env_remove("DISPLAY").env_remove("WAYLAND_DISPLAY").output().unwrap();
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("microtrace render"), "{stderr}");
    let output = Command::new(&binary).args(["view", "no-such-scene.mts"]).output().unwrap();
    assert!(!output.status.success());
    assert!(String::from_utf8_lossy(&output.stderr).contains("no-such-scene.mts"));
}
