//! The `microtrace` command as a user runs it: outputs, errors, and no partial files.

use std::path::Path;

mod common;

use common::{microtrace, scratch, text};

#[test]
fn renders_a_thesis_scene_to_png_and_every_file_format_round_trips() {
    let directory = scratch("formats");
    let path = |name: &str| directory.join(name).to_str().unwrap().to_owned();
    let output = microtrace(&[
        "render", "scenes/snooker.mts", "--size", "66x60", "--out", &path("image.png"), "--pga", &path("image.pga"),
        "--lut", &path("image.lut"), "--stats",
    ]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    let stderr = text(&output.stderr);
    assert!(stderr.contains("pixels            3960"), "{stderr}");
    let uncompressed =
        microtrace(&["render", "scenes/snooker.mts", "--size", "66x60", "--pga", &path("image.ff"), "--uncompressed"]);
    assert!(uncompressed.status.success(), "{}", text(&uncompressed.stderr));
    let ff = std::fs::read(path("image.ff")).unwrap();
    assert_eq!(&ff[..9], &[0xFF, 0, 0, 65, 0, 0, 0, 59, 0]);
    assert_eq!(ff.len(), 9 + 66 * 60);
    assert_eq!(std::fs::read(path("image.pga")).unwrap()[0], 0xD9);

    let png = microtrace_sim::files::read_png_rgb(Path::new(&path("image.png"))).unwrap();
    for file in ["image.pga", "image.ff"] {
        let decoded = microtrace(&["decode", &path(file), "--lut", &path("image.lut"), "--out", &path("decoded.png")]);
        assert!(decoded.status.success(), "{}", text(&decoded.stderr));
        assert_eq!(microtrace_sim::files::read_png_rgb(Path::new(&path("decoded.png"))).unwrap(), png, "{file}");
    }

    let rgb = microtrace(&[
        "render", "scenes/snooker.mts", "--size", "66x60", "--mode", "rgb", "--out", &path("rgb.png"), "--rgb", &path("image.rgb"),
    ]);
    assert!(rgb.status.success(), "{}", text(&rgb.stderr));
    let decoded = microtrace(&["decode", &path("image.rgb"), "--out", &path("decoded-rgb.png")]);
    assert!(decoded.status.success(), "{}", text(&decoded.stderr));
    assert_eq!(
        microtrace_sim::files::read_png_rgb(Path::new(&path("decoded-rgb.png"))).unwrap(),
        microtrace_sim::files::read_png_rgb(Path::new(&path("rgb.png"))).unwrap()
    );
}

#[test]
fn stats_json_has_exactly_the_table_keys() {
    let directory = scratch("json");
    let json_path = directory.join("stats.json");
    let output = microtrace(&["render", "scenes/lattice.mts", "--size", "47x48", "--stats-json", json_path.to_str().unwrap()]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    let json = std::fs::read_to_string(&json_path).unwrap();
    let keys: Vec<&str> = json.split('"').skip(1).step_by(2).collect();
    assert_eq!(
        keys,
        ["pixels", "rays_traced", "rays_intersected", "ro_tests", "ro_hits", "shadow_rays", "shadow_tests", "solid_leaf_tests", "preprocess_ms", "trace_ms"]
    );
    assert!(json.contains("\"pixels\": 2256,"), "{json}");
}

#[test]
fn a_scene_error_names_file_and_line_and_writes_nothing() {
    let directory = scratch("error");
    let scene = directory.join("broken.mts");
    std::fs::write(&scene, "viewport 0 9 0 9\nsphere\n  scale 1 0 1\n").unwrap();
    let image = directory.join("image.png");
    let output = microtrace(&["render", scene.to_str().unwrap(), "--out", image.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text(&output.stderr);
    assert!(stderr.contains("broken.mts:") && stderr.contains("line 3"), "{stderr}");
    assert!(!image.exists());
    assert_eq!(std::fs::read_dir(&directory).unwrap().count(), 1, "only the scene is left");
}

#[test]
fn missing_scene_and_bad_arguments_are_clear_errors() {
    let output = microtrace(&["render", "no-such-scene.mts", "--out", "x.png"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text(&output.stderr).contains("cannot read scene no-such-scene.mts"), "{}", text(&output.stderr));

    let output = microtrace(&["render", "scenes/snooker.mts", "--size", "0x10", "--out", "x.png"]);
    assert!(!output.status.success());
    assert!(text(&output.stderr).contains("1 to 8192"), "{}", text(&output.stderr));

    let output = microtrace(&["render", "scenes/snooker.mts", "--rgb", "x.rgb"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text(&output.stderr).contains("--mode rgb"), "{}", text(&output.stderr));

    let output = microtrace(&["render", "scenes/snooker.mts"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text(&output.stderr).contains("nothing to write"), "{}", text(&output.stderr));
}

#[test]
fn an_unwritable_output_leaves_no_file_behind() {
    let directory = scratch("unwritable");
    let image = directory.join("no-such-directory").join("image.png");
    let output = microtrace(&["render", "scenes/snooker.mts", "--size", "20x20", "--out", image.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text(&output.stderr).contains("cannot write"), "{}", text(&output.stderr));
    assert_eq!(std::fs::read_dir(&directory).unwrap().count(), 0);
}

#[test]
fn decode_rejects_a_file_that_is_not_an_image() {
    let directory = scratch("decode");
    let bogus = directory.join("bogus.pga");
    std::fs::write(&bogus, b"\x42not an image").unwrap();
    let output = microtrace(&["decode", bogus.to_str().unwrap(), "--out", directory.join("out.png").to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text(&output.stderr).contains("cannot decode"), "{}", text(&output.stderr));
    assert!(!directory.join("out.png").exists());
}

/// Renders `scene` with `options` on `threads` threads into `directory`, returning the image
/// file's bytes (the PGA file in PGA mode, the RGB file in RGB mode) and the statistics JSON.
fn render_on_threads(directory: &Path, scene: &str, options: &[&str], threads: &str) -> (Vec<u8>, String) {
    let rgb = options.contains(&"rgb");
    let image = directory.join(format!("threads-{threads}.{}", if rgb { "rgb" } else { "pga" }));
    let json = directory.join(format!("threads-{threads}.json"));
    let mut arguments = vec!["render", scene, "--threads", threads, if rgb { "--rgb" } else { "--pga" }, image.to_str().unwrap()];
    arguments.extend(["--stats-json", json.to_str().unwrap()]);
    arguments.extend(options);
    let output = microtrace(&arguments);
    assert!(output.status.success(), "{arguments:?}: {}", text(&output.stderr));
    (std::fs::read(&image).unwrap(), std::fs::read_to_string(&json).unwrap())
}

/// The value of `key` in the statistics JSON.
fn statistic(json: &str, key: &str) -> u64 {
    let after = &json[json.find(&format!("\"{key}\": ")).unwrap_or_else(|| panic!("no {key} in {json}")) + key.len() + 4..];
    after[..after.find([',', '}']).unwrap()].parse().unwrap()
}

#[test]
fn three_threads_render_the_single_threaded_image_byte_for_byte() {
    let directory = scratch("threads");
    // 61 rows: the last band of 8 rows is a partial one.
    let cases = [("scenes/snooker.mts", "128x64"), ("scenes/lattice.mts", "466x480"), ("scenes/lattice.mts", "100x61")];
    for (scene, size) in cases {
        for options in [&["--size", size][..], &["--size", size, "--mode", "rgb"], &["--size", size, "--number", "f32"]] {
            let (one_image, one_json) = render_on_threads(&directory, scene, options, "1");
            let (three_image, three_json) = render_on_threads(&directory, scene, options, "3");
            assert!(one_image.len() > 9, "{scene} {options:?}: an image was written");
            assert!(one_image == three_image, "{scene} {options:?}: --threads 3 renders a different image from --threads 1");
            // The caches restart at each band, so only the test counts may differ.
            for key in ["pixels", "rays_traced", "rays_intersected", "shadow_rays"] {
                assert_eq!(statistic(&one_json, key), statistic(&three_json, key), "{scene} {options:?}: {key}");
            }
        }
    }
}

#[test]
fn zero_threads_is_a_clear_error() {
    let directory = scratch("zero-threads");
    let image = directory.join("image.png");
    let output = microtrace(&["render", "scenes/snooker.mts", "--size", "20x20", "--threads", "0", "--out", image.to_str().unwrap()]);
    assert!(!output.status.success());
    assert!(text(&output.stderr).contains("at least 1"), "{}", text(&output.stderr));
    assert!(!image.exists());
}

#[test]
fn progressive_renders_the_same_image_and_counts_each_pass() {
    let directory = scratch("progressive");
    for (scene, options) in [("scenes/snooker.mts", &["--size", "131x60"][..]), ("scenes/lattice.mts", &["--size", "100x61", "--mode", "rgb"])] {
        let (normal_image, normal_json) = render_on_threads(&directory, scene, options, "1");
        let rgb = options.contains(&"rgb");
        let image = directory.join(if rgb { "progressive.rgb" } else { "progressive.pga" });
        let json = directory.join("progressive.json");
        let mut arguments = vec!["render", scene, "--progressive", "--stats", if rgb { "--rgb" } else { "--pga" }, image.to_str().unwrap()];
        arguments.extend(["--stats-json", json.to_str().unwrap()]);
        arguments.extend(options);
        let output = microtrace(&arguments);
        assert!(output.status.success(), "{arguments:?}: {}", text(&output.stderr));
        assert!(std::fs::read(&image).unwrap() == normal_image, "{scene} {options:?}: --progressive renders a different image");
        let json = std::fs::read_to_string(&json).unwrap();
        for key in ["pixels", "rays_traced", "rays_intersected", "shadow_rays"] {
            assert_eq!(statistic(&json, key), statistic(&normal_json, key), "{scene}: {key}");
        }
        // Each pass's counts, in order 8, 4, 2, 1; their rays add up to the whole render's.
        let passes = &json[json.find("\"passes\"").expect("passes in the JSON")..];
        let each: Vec<&str> = passes.split("{\"block\"").skip(1).collect();
        assert_eq!(each.len(), 4, "{passes}");
        let blocks: Vec<u64> = each.iter().map(|pass| pass[2..pass.find(',').unwrap()].parse().unwrap()).collect();
        assert_eq!(blocks, [8, 4, 2, 1]);
        let rays: Vec<u64> = each.iter().map(|pass| statistic(pass, "rays_traced")).collect();
        assert_eq!(rays.iter().sum::<u64>(), statistic(&json, "rays_traced"));
        assert!(rays[0] > 0 && rays[0] * 10 < rays[3], "{rays:?}: the first pass traces about one pixel in 64, the last 3 in 4");
        let stderr = text(&output.stderr);
        assert!(stderr.contains(&format!("pass 1 (8x8)    {} rays", rays[0])) && stderr.contains("pass 4 (1x1)"), "{stderr}");
    }
    let output = microtrace(&["render", "scenes/snooker.mts", "--progressive", "--threads", "2", "--stats"]);
    assert!(!output.status.success(), "--progressive with --threads is refused");
}

/// `render --display KIND` writes the picture the display shows: the window's preview of it,
/// pixel for pixel (the same core path as the firmware's), black and white dots for the SSD1306,
/// and the error diffusion (the default) other dots than the ordered dither.
#[test]
fn render_display_writes_the_displays_picture() {
    use microtrace_sim::commands::view::ui::preview::{self, DisplayKind};
    let directory = scratch("display");
    let scene = microtrace_sim::scene_file::load(Path::new("../scenes/snooker.mts")).unwrap();
    let mut pictures = Vec::new();
    for (name, kind) in [("ssd1306", DisplayKind::Ssd1306), ("ssd1306-ordered", DisplayKind::Ssd1306Ordered), ("rgb565", DisplayKind::Rgb565)] {
        let out = directory.join(format!("{name}.png"));
        let output = microtrace(&["render", "scenes/snooker.mts", "--number", "f32", "--display", name, "--out", out.to_str().unwrap()]);
        assert!(output.status.success(), "{name}: {}", text(&output.stderr));
        let (width, height, written) = microtrace_sim::files::read_png_rgb(&out).unwrap();
        let (display_width, display_height) = kind.size();
        assert_eq!((width, height), (u32::from(display_width), u32::from(display_height)), "{name}");
        let shown = preview::render(&scene, microtrace::number::NumberKind::F32, kind).unwrap();
        let expected: Vec<[u8; 3]> = shown.pixels.iter().map(|colour| {
            use embedded_graphics::pixelcolor::RgbColor;
            [colour.r(), colour.g(), colour.b()]
        }).collect();
        assert!(written == expected, "{name}: the written picture differs from the preview");
        if name.starts_with("ssd1306") {
            assert!(written.iter().all(|dot| *dot == [0; 3] || *dot == [255; 3]), "{name}: not black and white");
        }
        pictures.push(written);
    }
    assert_ne!(pictures[0], pictures[1], "error diffusion drew the ordered dither's dots");
    // A display picture is the only output: with another one it is refused.
    let refused = microtrace(&["render", "scenes/snooker.mts", "--display", "ssd1306", "--out", directory.join("x.png").to_str().unwrap(), "--stats"]);
    assert!(!refused.status.success());
}

/// `microtrace volume`: each object's volume with its error estimate, the torus's among them
/// (2π²·R·r² scaled: scenes/torus.mts's `torus 0.3` scaled by 40 is 113,699); a scene without
/// objects, or a missing file, is an error naming the file.
#[test]
fn volume_gives_each_objects_volume_and_its_error() {
    let output = microtrace(&["volume", "scenes/torus.mts", "--size", "128"]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    let stdout = text(&output.stdout);
    let line = stdout.lines().find(|line| line.starts_with("object 2 (torus, line 23): volume ")).unwrap_or_else(|| panic!("{stdout}"));
    let numbers: Vec<f64> = line.split(['(', ')', ' ', '±']).filter_map(|word| word.parse().ok()).collect();
    let (volume, error) = (numbers[2], numbers[3]);
    let exact = 2.0 * std::f64::consts::PI.powi(2) * 0.3 * 0.3 * 40f64.powi(3);
    assert!((volume - exact).abs() <= error && error < exact * 0.05, "{line}: exact {exact}");
    assert_eq!(stdout.lines().count(), 4, "{stdout}");

    let directory = scratch("volume");
    let empty = directory.join("empty.mts");
    std::fs::write(&empty, "viewport 0 9 0 9\n").unwrap();
    let output = microtrace(&["volume", empty.to_str().unwrap()]);
    assert!(!output.status.success());
    assert!(text(&output.stderr).contains("empty.mts: the scene has no objects"), "{}", text(&output.stderr));
    let output = microtrace(&["volume", "no-such-scene.mts"]);
    assert!(!output.status.success() && text(&output.stderr).contains("no-such-scene.mts"), "{}", text(&output.stderr));
}

/// `render --edges`: a black line on white where a pixel's first surface differs from its left
/// or upper neighbour's: for a square in a parallel view, its left and top rows of pixels and
/// the background pixels just right of and below it.
#[test]
fn edges_draw_where_the_first_surface_changes() {
    let directory = scratch("edges");
    let scene = directory.join("square.mts");
    // 16 x 16 pixels sampling x, y = −8 + 16/15·i: the cube [−3, 3]² covers columns and rows 5..=10.
    std::fs::write(&scene, "viewport 0 15 0 15\nwindow -8 8 -8 8\nviewplane 10\nparallel 0 0 -1\ncube\n  scale 6 6 6\n  translate -3 -3 -3\n").unwrap();
    let out = directory.join("edges.png");
    let output = microtrace(&["render", scene.to_str().unwrap(), "--edges", "--out", out.to_str().unwrap()]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    let (width, height, pixels) = microtrace_sim::files::read_png_rgb(&out).unwrap();
    assert_eq!((width, height), (16, 16));
    let black: Vec<(usize, usize)> = (0..256).filter(|i| pixels[*i] == [0, 0, 0]).map(|i| (i % 16, i / 16)).collect();
    assert!(pixels.iter().all(|p| *p == [0, 0, 0] || *p == [255, 255, 255]), "only black and white");
    let mut expected: Vec<(usize, usize)> = Vec::new();
    for row in 0..16 {
        for column in 0..16 {
            let inside = |c: usize, r: usize| (5..=10).contains(&c) && (5..=10).contains(&r);
            let here = inside(column, row);
            if (column > 0 && inside(column - 1, row) != here) || (row > 0 && inside(column, row - 1) != here) {
                expected.push((column, row));
            }
        }
    }
    assert_eq!(black, expected);
    assert_eq!(black.len(), 23);
}

/// A scene that parses but may not look as meant is rendered with a warning naming the line:
/// the eye inside an object, a light inside an opaque one, no light statement; a scene with
/// none of these gets none.
#[test]
fn a_scene_that_may_not_look_right_is_rendered_with_a_warning() {
    let directory = scratch("warnings");
    let out = directory.join("inside.png");
    let output = microtrace(&["render", "scenes/hard/eye_inside.mts", "--size", "16x16", "--out", out.to_str().unwrap()]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    let stderr = text(&output.stderr);
    assert!(stderr.contains("scenes/hard/eye_inside.mts:line 9: warning: the eye is inside the object of line 9"), "{stderr}");
    assert!(stderr.contains("scenes/hard/eye_inside.mts:line 7: warning: the light of line 7 is inside the opaque object of line 9"), "{stderr}");
    let unlit = directory.join("unlit.mts");
    std::fs::write(&unlit, "perspective 0 0 10\nsphere\n").unwrap();
    let output = microtrace(&["render", unlit.to_str().unwrap(), "--size", "16x16", "--out", directory.join("unlit.png").to_str().unwrap()]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    assert!(text(&output.stderr).contains("unlit.mts: warning: no `light` statement: the default light is used"), "{}", text(&output.stderr));
    let output = microtrace(&["render", "scenes/snooker.mts", "--size", "16x16", "--out", directory.join("snooker.png").to_str().unwrap()]);
    assert!(!text(&output.stderr).contains("warning"), "{}", text(&output.stderr));
}
