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

/// The `microtrace` binary, built by cargo for this test with the window program
/// `microtrace view` runs (`microtrace-view`, beside it: cargo builds every binary of the package
/// for its integration tests, in the test's own profile).
fn microtrace_binary() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_microtrace"))
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

/// `E` shows the edge image in place of the picture: the window's image area is `render
/// --edges`'s, pixel for pixel (the torus scene: its rings' outlines and the hole's).
#[test]
fn e_shows_the_edge_image_of_render_edges() {
    let Some((display, _xvfb)) = display_or_skip() else { return };
    let binary = microtrace_binary();
    let ((window_width, _, window), _) = screenshot_and_stderr(&binary, &display, "torus", &["--keys", "e"]);
    let dir = std::env::temp_dir().join(format!("microtrace-view-{}-edges", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let reference = dir.join("edges.png");
    let status = Command::new(&binary)
        .arg("render")
        .arg(workspace().join("scenes/torus.mts"))
        .args(["--size", "132x120", "--edges", "--out"])
        .arg(&reference)
        .status()
        .expect("run microtrace render");
    assert!(status.success());
    let (width, height, expected) = read_png(&reference);
    let differing = (0..height).flat_map(|y| (0..width).map(move |x| (x, y))).filter(|&(x, y)| window[(y * window_width + x) as usize] != expected[(y * width + x) as usize]).count();
    assert_eq!(differing, 0, "{differing} pixels of the window's edge image differ from `render --edges`");
    let black = expected.iter().filter(|p| **p == [0, 0, 0]).count();
    assert!(black > 100 && black < (width * height / 4) as usize, "{black} edge pixels");
    let _ = std::fs::remove_dir_all(&dir);
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

/// A black-and-white picture in memory, for the error diffusion's expected dots.
struct Dots {
    width: u32,
    lit: Vec<bool>,
}

impl embedded_graphics::prelude::OriginDimensions for Dots {
    fn size(&self) -> embedded_graphics::prelude::Size {
        embedded_graphics::prelude::Size::new(self.width, self.lit.len() as u32 / self.width)
    }
}

impl embedded_graphics::prelude::DrawTarget for Dots {
    type Color = embedded_graphics::pixelcolor::BinaryColor;
    type Error = std::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = embedded_graphics::Pixel<Self::Color>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for embedded_graphics::Pixel(point, colour) in pixels {
            self.lit[(point.y as u32 * self.width + point.x as u32) as usize] = colour.is_on();
        }
        Ok(())
    }
}

/// Each display preview (`--display oled|ssd1306|ssd1306-ordered|rgb565`, which `L` cycles)
/// shows, pixel for pixel, the core's image of the scene fitted to that display through the
/// firmware's mapping: the look-up table's grey (`grey_level`) on the 16-grey OLED; on the
/// 1-bit SSD1306 the entry's 8-bit luma error-diffused (`ErrorDiffusion`, the dots in row
/// order), or that grey through the 4x4 ordered dither (`dither_lights`); the look-up table's
/// colour in RGB565 (`lut_colour::<Rgb565>`) on the colour panel.
#[test]
fn each_display_preview_shows_the_core_image_through_its_mapping() {
    use embedded_graphics::pixelcolor::{Gray8, GrayColor, Rgb565, Rgb888, RgbColor};
    use embedded_graphics::prelude::{DrawTarget, Point};
    use microtrace::pixel::{dither_lights, grey_level, lut_colour, ErrorDiffusion, FrameBuffer};
    let Some((display, _xvfb)) = display_or_skip() else { return };
    let binary = microtrace_binary();
    for scene in ["snooker", "lattice"] {
        let text = std::fs::read(workspace().join("scenes").join(format!("{scene}.mts"))).unwrap();
        let mut description = microtrace::parser::parse::<64>(&text).unwrap();
        description.fit_to_size(132, 120);
        for (kind, width, height, zoom) in [("oled", 128u16, 64u16, 2u32), ("ssd1306", 128, 64, 2), ("ssd1306-ordered", 128, 64, 2), ("rgb565", 240, 240, 1)] {
            let mut fitted = description.clone();
            fitted.fit_to_size(width, height);
            let prepared = microtrace::scene::Scene::<f64, 64>::prepare(&fitted).unwrap();
            let mut indices = vec![0u8; usize::from(width) * usize::from(height)];
            microtrace::render::render(&prepared, microtrace::render::Pga, microtrace::render::Whole, &mut FrameBuffer::new(&mut indices, width, height).unwrap(), &mut microtrace::render::Statistics::default());
            let palette = &fitted.palette;
            // The diffused dots, each row's dots fed left to right, rows top first.
            let mut diffused = ErrorDiffusion::<_, 128>::new(Dots { width: u32::from(width), lit: vec![false; indices.len()] });
            let in_order = indices.iter().enumerate().map(|(i, index)| {
                let point = Point::new((i % usize::from(width)) as i32, (i / usize::from(width)) as i32);
                embedded_graphics::Pixel(point, Gray8::new(palette.entry(*index).luma8()))
            });
            diffused.draw_iter(in_order).unwrap();
            let diffused = diffused.into_inner().lit;
            let expected: Vec<[u8; 3]> = indices
                .iter()
                .enumerate()
                .map(|(i, index)| {
                    let point = Point::new((i % usize::from(width)) as i32, (i / usize::from(width)) as i32);
                    let grey = grey_level(palette, *index).luma();
                    match kind {
                        "oled" => [grey * 17; 3],
                        "ssd1306" => if diffused[i] { [255; 3] } else { [0; 3] },
                        "ssd1306-ordered" => if dither_lights(grey, point) { [255; 3] } else { [0; 3] },
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

/// The window's image area (the top-left 132x120 pixels) of a screenshot.
fn image_area((width, _, window): &(u32, u32, Vec<[u8; 3]>)) -> Vec<[u8; 3]> {
    (0..120).flat_map(|y| (0..132).map(move |x| (y * width + x) as usize)).map(|i| window[i]).collect()
}

/// Whether the screenshot shows `text` as the panel writes it (FONT_6X10 in light grey on
/// black, `view/panel.rs`) somewhere right of the image.
fn panel_shows((width, height, window): &(u32, u32, Vec<[u8; 3]>), text: &str) -> bool {
    use embedded_graphics::mono_font::{ascii::FONT_6X10, MonoTextStyle};
    use embedded_graphics::pixelcolor::BinaryColor;
    use embedded_graphics::prelude::*;
    use embedded_graphics::text::{Baseline, Text};
    struct Glyphs {
        width: u32,
        lit: Vec<bool>,
    }
    impl OriginDimensions for Glyphs {
        fn size(&self) -> Size {
            Size::new(self.width, 10)
        }
    }
    impl DrawTarget for Glyphs {
        type Color = BinaryColor;
        type Error = std::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
            for Pixel(point, colour) in pixels {
                if (0..self.width as i32).contains(&point.x) && (0..10).contains(&point.y) {
                    self.lit[(point.y as u32 * self.width + point.x as u32) as usize] = colour.is_on();
                }
            }
            Ok(())
        }
    }
    let glyph_width = 6 * text.chars().count() as u32;
    let mut glyphs = Glyphs { width: glyph_width, lit: vec![false; (glyph_width * 10) as usize] };
    let _ = Text::with_baseline(text, Point::zero(), MonoTextStyle::new(&FONT_6X10, BinaryColor::On), Baseline::Top).draw(&mut glyphs);
    let Some(first) = glyphs.lit.iter().position(|lit| *lit) else { return true };
    let (first_x, first_y) = (first as u32 % glyph_width, first as u32 / glyph_width);
    let text_colour = [230, 230, 230];
    (0..height.saturating_sub(9)).any(|top| {
        (132..width.saturating_sub(glyph_width - 1)).any(|left| {
            window[((top + first_y) * width + left + first_x) as usize] == text_colour
                && (0..10).all(|y| (0..glyph_width).all(|x| (window[((top + y) * width + left + x) as usize] == text_colour) == glyphs.lit[(y * glyph_width + x) as usize]))
        })
    })
}

/// Asserts that the panel shows each part of a ray line `view` printed.
fn assert_panel_shows(screenshot: &(u32, u32, Vec<[u8; 3]>), line: &str) {
    for part in line.split("; ") {
        assert!(panel_shows(screenshot, part), "the panel does not show {part:?}");
    }
}

/// `microtrace render` of the scene `text` (written to a file of its own) at 132x120.
fn render_text(binary: &Path, name: &str, text: &str) -> Vec<[u8; 3]> {
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("microtrace-view-{}-render-{call}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (scene, image) = (dir.join(format!("{name}.mts")), dir.join("render.png"));
    std::fs::write(&scene, text).unwrap();
    let output = Command::new(binary).arg("render").arg(&scene).args(["--size", "132x120", "--out"]).arg(&image).output().expect("run microtrace render");
    assert!(output.status.success(), "render {name}: {}", String::from_utf8_lossy(&output.stderr));
    let (width, height, pixels) = read_png(&image);
    assert_eq!((width, height), (132, 120));
    let _ = std::fs::remove_dir_all(&dir);
    pixels
}

fn scene_text(scene: &str) -> String {
    std::fs::read_to_string(workspace().join("scenes").join(format!("{scene}.mts"))).unwrap()
}

/// The ray lines `view` prints after each render (the panel's depth, antialiasing, rays per
/// pixel and secondary rays), in order.
fn ray_lines(stderr: &str) -> Vec<&str> {
    stderr.lines().filter(|line| line.starts_with("depth ")).collect()
}

/// The rays per pixel a ray line states.
fn rays_per_pixel(line: &str) -> f64 {
    let after = line.split("rays per pixel ").nth(1).unwrap_or_else(|| panic!("no rays per pixel in {line:?}"));
    after.split_whitespace().next().and_then(|number| number.parse().ok()).unwrap_or_else(|| panic!("no number in {line:?}"))
}

/// The secondary rays a ray line states (0: none).
fn secondary_rays(line: &str) -> u64 {
    match line.split("secondary rays ").nth(1) {
        Some(after) => after.split(',').next().and_then(|number| number.parse().ok()).unwrap_or_else(|| panic!("no number in {line:?}")),
        None => {
            assert!(line.contains("no secondary rays"), "{line:?}");
            0
        }
    }
}

/// `T` cycles the ray tree's depth from the scene's own (snooker-polished: 4) up to 8 and round
/// to 1, re-rendering each time: at depth 1 the window shows the scene with every `reflect` and
/// `transmit` zeroed (what `render` makes of that file; the glass ball's lighter shadow falls on
/// no ball in this view), and eight presses bring back the scene's own image.
#[test]
fn the_depth_key_cycles_the_ray_tree() {
    let Some((display, _xvfb)) = display_or_skip() else { return };
    let binary = microtrace_binary();
    let scene = "snooker-polished";
    let (own, stderr) = screenshot_and_stderr(&binary, &display, scene, &[]);
    assert_eq!(ray_lines(&stderr).len(), 1, "{stderr}");
    let own_line = ray_lines(&stderr)[0].to_owned();
    assert!(own_line.starts_with("depth 4 ") && own_line.contains("secondary rays "), "{stderr}");

    let (shallow, stderr) = screenshot_and_stderr(&binary, &display, scene, &["--keys", "TTTTT"]);
    let depths: Vec<&str> = ray_lines(&stderr).iter().map(|line| line.split("  ").next().unwrap_or_default()).collect();
    assert_eq!(depths, ["depth 4", "depth 5", "depth 6", "depth 7", "depth 8", "depth 1"], "{stderr}");
    let last = ray_lines(&stderr)[5];
    assert!(last.contains("no secondary rays"), "{last}");
    // Deeper trees trace more secondary rays.
    let secondary: Vec<u64> = ray_lines(&stderr).iter().map(|line| secondary_rays(line)).collect();
    assert!(secondary[0] > 0 && secondary[0] < secondary[1] && secondary[1] <= secondary[4] && secondary[5] == 0, "{secondary:?}");

    let zeroed: String = scene_text(scene)
        .lines()
        .map(|line| match line.split_whitespace().next() {
            Some(keyword @ ("reflect" | "transmit")) => format!("  {keyword} 0\n"),
            _ => format!("{line}\n"),
        })
        .collect();
    assert!(zeroed != scene_text(scene));
    let expected = render_text(&binary, "zeroed", &zeroed);
    let shown = image_area(&shallow);
    let differing = shown.iter().zip(&expected).filter(|(a, b)| a != b).count();
    assert_eq!(differing, 0, "depth 1: {differing} pixels differ from the scene without reflection and transmission");
    assert!(image_area(&own) != shown, "depth 4 and depth 1 look the same: the scene's tree is not drawn");
    assert_panel_shows(&own, &own_line);
    assert_panel_shows(&shallow, last);
    assert!(!panel_shows(&shallow, "depth 4") && !panel_shows(&own, "no secondary rays"), "the panel shows a depth it is not at");

    let (round, stderr) = screenshot_and_stderr(&binary, &display, scene, &["--keys", "TTTTTTTT"]);
    assert!(ray_lines(&stderr).last().is_some_and(|line| line.starts_with("depth 4 ")), "{stderr}");
    assert!(image_area(&round) == image_area(&own), "eight presses of T should bring back the scene's depth");
}

/// `A` turns antialiasing on at level 1 with the threshold 0.1 when the scene has none
/// (snooker-polished: the image is then `render`'s of the scene with `antialias 0.1 1`), and
/// cycles the scene's own (lattice-antialiased: 0.06, level 2) up to level 4 and off (the image
/// is then the plain lattice's; off to level 1 again is `rays.rs`'s unit test). Rays per pixel
/// (in the panel, and printed with it) rise with antialiasing and with each level, and are at
/// most 1 without (Pixelbuffer on).
#[test]
fn the_antialiasing_key_cycles_the_levels_and_changes_rays_per_pixel() {
    let Some((display, _xvfb)) = display_or_skip() else { return };
    let binary = microtrace_binary();

    let (plain, stderr) = screenshot_and_stderr(&binary, &display, "snooker-polished", &[]);
    let before = ray_lines(&stderr)[0].to_owned();
    assert!(before.contains("antialias off") && rays_per_pixel(&before) <= 1.0, "{before}");
    let (smooth, stderr) = screenshot_and_stderr(&binary, &display, "snooker-polished", &["--keys", "A"]);
    let after = *ray_lines(&stderr).last().unwrap();
    assert!(after.contains("antialias L1 threshold 0.10") && rays_per_pixel(after) > rays_per_pixel(&before), "{after}");
    let expected = render_text(&binary, "antialiased", &format!("{}\nantialias 0.1 1\n", scene_text("snooker-polished")));
    let shown = image_area(&smooth);
    assert!(shown != image_area(&plain), "antialiasing changed nothing");
    let differing = shown.iter().zip(&expected).filter(|(a, b)| a != b).count();
    assert_eq!(differing, 0, "A: {differing} pixels differ from the scene rendered with `antialias 0.1 1`");
    assert_panel_shows(&plain, &before);
    assert_panel_shows(&smooth, after);
    assert!(!panel_shows(&smooth, "antialias off") && !panel_shows(&plain, "antialias L1"), "the panel shows antialiasing it is not at");

    let (off, stderr) = screenshot_and_stderr(&binary, &display, "lattice-antialiased", &["--keys", "AAA"]);
    let lines = ray_lines(&stderr);
    let settings: Vec<&str> = lines.iter().map(|line| line.split("; ").next().unwrap_or_default()).collect();
    assert_eq!(settings, ["depth 5  antialias L2 threshold 0.06", "depth 5  antialias L3 threshold 0.06", "depth 5  antialias L4 threshold 0.06", "depth 5  antialias off"], "{stderr}");
    let per_pixel: Vec<f64> = lines.iter().map(|line| rays_per_pixel(line)).collect();
    assert!(per_pixel[0] > 1.0 && per_pixel[0] < per_pixel[1] && per_pixel[1] < per_pixel[2] && per_pixel[3] <= 1.0, "{per_pixel:?}");
    let expected = render_text(&binary, "lattice", &scene_text("lattice"));
    let differing = image_area(&off).iter().zip(&expected).filter(|(a, b)| a != b).count();
    assert_eq!(differing, 0, "antialiasing off: {differing} pixels differ from the plain lattice");
    assert_panel_shows(&off, lines[3]);
    let (own, stderr) = screenshot_and_stderr(&binary, &display, "lattice-antialiased", &[]);
    assert!(image_area(&own) != image_area(&off), "the lattice's antialiasing changed nothing");
    assert_panel_shows(&own, ray_lines(&stderr)[0]);
}
