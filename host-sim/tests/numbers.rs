//! Every number type through the command line: `render --number` on the thesis scenes at
//! 128x64 against f64, and `bench --numbers` end to end on small scenes.

use std::path::Path;

use microtrace_sim::image_difference::ImageDifference;
use microtrace::number::NumberKind;

mod common;

use common::{microtrace, scratch, text};

/// Renders `scene` at 128x64 with `number` and returns the palette indices (the data of the
/// uncompressed PGA file after its 9-byte header).
fn render_indices(directory: &Path, scene: &str, number: &str) -> Vec<u8> {
    let file = directory.join(format!("{number}.pga"));
    let output = microtrace(&["render", scene, "--size", "128x64", "--number", number, "--pga", file.to_str().unwrap(), "--uncompressed"]);
    assert!(output.status.success(), "{scene} {number}: {}", text(&output.stderr));
    let bytes = std::fs::read(&file).unwrap();
    assert_eq!(bytes.len(), 9 + 128 * 64, "{scene} {number}");
    bytes[9..].to_vec()
}

#[test]
fn every_number_type_renders_both_thesis_scenes_close_to_f64() {
    for scene in ["scenes/snooker.mts", "scenes/lattice.mts"] {
        let directory = scratch(scene.trim_start_matches("scenes/").trim_end_matches(".mts"));
        let palette = microtrace_sim::scene_file::load(Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(scene).as_path())
            .unwrap()
            .palette;
        let reference = render_indices(&directory, scene, "f64");
        let distinct = |indices: &[u8]| indices.iter().collect::<std::collections::BTreeSet<_>>().len();
        assert!(distinct(&reference) > 10, "{scene}: the f64 image has only {} indices", distinct(&reference));
        for number in NumberKind::ALL.iter().map(|n| n.name()) {
            let image = render_indices(&directory, scene, number);
            let difference = ImageDifference::measure(&reference, &image, 128, 64, &palette).unwrap();
            let identical = difference.percent_identical();
            let context = format!("{scene} {number}: {difference:?}");
            assert!(distinct(&image) > 10, "{context}: a nearly blank image");
            match number {
                "f64" => assert_eq!(difference.differing, 0, "{context}: f64 is not reproducible"),
                // soft32 is held to f32's target.
                "f32" | "soft32" => assert!(identical >= 99.95, "{context}"),
                "fixed" => {
                    assert!(identical >= 99.5, "{context}");
                    assert!(difference.largest_shade_step <= 1 && difference.group_changes == 0, "{context}");
                    assert_eq!(difference.speckles, 0, "{context}");
                }
                // Less accurate by design (docs/numbers.md): measured 98.3–99.3 % and 92.7 %.
                "fixed16" => assert!(identical >= 97.0, "{context}"),
                "f32-micromath" => assert!(identical >= 90.0, "{context}"),
                other => panic!("a number type without a check: {other}"),
            }
        }
    }
}

#[test]
fn an_unknown_number_type_is_refused_with_the_valid_names() {
    let output = microtrace(&["render", "scenes/snooker.mts", "--number", "q15", "--stats"]);
    assert!(!output.status.success());
    let stderr = text(&output.stderr);
    for name in ["f64", "f32", "fixed", "fixed16", "f32-micromath", "soft32"] {
        assert!(stderr.contains(name), "{name} missing from: {stderr}");
    }
}

#[test]
fn a_scene_beyond_fixed_range_is_an_error_naming_the_type() {
    let directory = scratch("range");
    let scene = directory.join("far.mts");
    std::fs::write(&scene, FAR_SCENE).unwrap();
    let png = directory.join("far.png");
    let arguments = |number| ["render", scene.to_str().unwrap(), "--number", number, "--out", png.to_str().unwrap()];
    let fixed = microtrace(&arguments("fixed"));
    assert!(!fixed.status.success());
    assert!(text(&fixed.stderr).contains("`fixed`"), "{}", text(&fixed.stderr));
    // A preparation error names the file and the line of the statement, as a parse error does.
    let expected = format!("microtrace: {}:line 4: the eye reaches 30000", scene.display());
    assert!(text(&fixed.stderr).starts_with(&expected), "{}", text(&fixed.stderr));
    assert!(!png.exists(), "a failed render wrote {}", png.display());
    let float = microtrace(&arguments("f32"));
    assert!(float.status.success(), "{}", text(&float.stderr));
}

/// A sphere 30 000 units from the origin: beyond fixed's ±26 000 and fixed16's ±16 384.
const FAR_SCENE: &str = "viewport 0 31 0 15\nwindow -2 2 -1 1\nviewplane 10\nperspective 30000 0 20\n\
                         light point 30000 10 20\nsphere\n  translate 30000 0 0\n";

#[test]
fn bench_numbers_reports_every_type_out_of_range_scenes_and_firmware_figures() {
    let directory = scratch("bench");
    let scenes = directory.join("scenes");
    std::fs::create_dir_all(scenes.join("hard")).unwrap();
    // The thesis scenes, shrunk so the test is quick: only the viewport line changes.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    for (file, viewport) in [("snooker.mts", "viewport 0 527 0 479"), ("lattice.mts", "viewport 0 465 0 479")] {
        let original = std::fs::read_to_string(root.join("scenes").join(file)).unwrap();
        assert!(original.contains(viewport), "{file} no longer has `{viewport}`");
        std::fs::write(scenes.join(file), original.replace(viewport, "viewport 0 43 0 39")).unwrap();
    }
    std::fs::write(scenes.join("hard/far.mts"), FAR_SCENE).unwrap();
    std::fs::write(scenes.join("hard/broken.mts"), "viewport 0 31 0 15\nsphere\n  frobnicate 1\n").unwrap();
    std::fs::write(scenes.join("hard/notes.txt"), "not a scene").unwrap();
    let firmware = directory.join("firmware-report.json");
    std::fs::write(
        &firmware,
        r#"{"runs":[{"scene":"snooker","board":"lm3s6965evb","number":"f32","instructions_per_pixel":1000,"frame_instructions":8192000},
                    {"scene":"snooker","board":"lm3s6965evb","number":"fixed","instructions_per_pixel":500,"frame_instructions":4096000},
                    {"scene":"lattice","board":"lm3s6965evb","number":"f32","instructions_per_pixel":2000,"instructions":16384000},
                    {"scene":"lattice","board":"lm3s6965evb","number":"fixed","instructions_per_pixel":1000},
                    {"scene":"lattice","board":"mps2-an386","number":"f32","instructions_per_pixel":333,"frame_instructions":2727936},
                    {"scene":"lattice","board":"microbit","number":"f32","instructions_per_pixel":11246,"frame_instructions":92129190},
                    {"scene":"snooker","board":"mps2-an505","number":"f32","instructions_per_pixel":277,"frame_instructions":2271093}]}"#,
    )
    .unwrap();
    let report = directory.join("numbers.md");
    std::fs::write(&report, "old text\n## Notes (hand-written, kept by `bench --numbers`)\n\nKeep this line.\n").unwrap();
    let plot = directory.join("images/numbers.png");
    let output = microtrace(&[
        "bench",
        "--numbers",
        "--scenes",
        scenes.to_str().unwrap(),
        "--out",
        report.to_str().unwrap(),
        "--plot",
        plot.to_str().unwrap(),
        "--firmware-report",
        firmware.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{}", text(&output.stderr));
    let markdown = std::fs::read_to_string(&report).unwrap();
    assert!(!markdown.contains("old text"), "the generated part was not rewritten");
    assert!(markdown.ends_with("Keep this line.\n"), "the hand-written notes were lost:\n{markdown}");
    assert!(markdown.contains("![speed against error](images/numbers.png)"), "{markdown}");
    // Every type on every readable scene, the out-of-range ones said so, the broken file named.
    for number in ["f64", "f32", "fixed", "fixed16", "f32-micromath", "soft32"] {
        for scene in ["snooker 44x40", "lattice 44x40", "snooker 128x64", "lattice 128x64", "far 32x16"] {
            assert!(markdown.contains(&format!("| {scene} | {number} |")), "no row for {scene} {number}:\n{markdown}");
        }
    }
    assert!(markdown.contains("| far 32x16 | fixed | **out of range**: line 4: the eye reaches ") && markdown.contains("`fixed`,"), "{markdown}");
    assert!(markdown.contains("| far 32x16 | fixed16 | **out of range**"), "{markdown}");
    assert!(markdown.contains("- `broken`: "), "{markdown}");
    assert!(!markdown.lines().any(|line| line.starts_with("| notes ")) && !markdown.contains("`notes`"), "a .txt file was taken for a scene");
    // 1000 / 500 = 2x and 2000 / 1000 = 2x: short of 3x, said plainly.
    assert!(markdown.contains("snooker: f32 1000 / fixed 500 = 2.00x; lattice: f32 2000 / fixed 1000 = 2.00x | **NOT met** |"), "{markdown}");
    assert!(markdown.contains("**Not met: the Cortex-M3 speed target.**"), "{markdown}");
    // soft32 has its own rows; the figures above have no soft32 entry.
    assert!(markdown.contains("| soft32 (software floating point): f32's target"), "{markdown}");
    assert!(markdown.contains("snooker, optimizations off: no entry in ") && markdown.contains("| not measured |"), "{markdown}");
    let lattice_small_f32 = markdown.lines().find(|line| line.starts_with("| lattice 128x64 | f32 |")).unwrap();
    // M0, M3, M4F and M33, in that order.
    assert!(lattice_small_f32.ends_with("| 11246 | 2000 | 333 | — |"), "{lattice_small_f32}");
    // The full-size rows have no firmware figures (those are 128x64 renders).
    let snooker_small_fixed = markdown.lines().find(|line| line.starts_with("| snooker 44x40 | fixed |")).unwrap();
    assert!(snooker_small_fixed.ends_with("| — | — | — | — |"), "{snooker_small_fixed}");
    // The host panel on top (640 rows), below it the Cortex-M0 and Cortex-M3 panels side by
    // side, then the Cortex-M4F and Cortex-M33, with points where the report has instructions
    // per frame (`frame_instructions`, or `instructions`).
    let (width, height, pixels) = microtrace_sim::files::read_png_rgb(&plot).unwrap();
    assert_eq!((width, height), (1000, 1680));
    let coloured = |rows: std::ops::Range<usize>, columns: std::ops::Range<usize>| {
        rows.flat_map(|row| columns.clone().map(move |column| row * width as usize + column))
            .filter(|&at| {
                let [r, g, b] = pixels[at];
                r.abs_diff(g) > 60 || g.abs_diff(b) > 60
            })
            .count()
    };
    let host = coloured(0..640, 0..1000);
    assert!(host > 100, "the host panel has only {host} coloured pixels: no points drawn?");
    let cortex_m0 = coloured(640..1160, 0..500);
    let cortex_m3 = coloured(640..1160, 500..1000);
    let cortex_m4f = coloured(1160..1680, 0..500);
    let cortex_m33 = coloured(1160..1680, 500..1000);
    assert!(cortex_m0 > 20, "the Cortex-M0 panel has only {cortex_m0} coloured pixels: no point drawn?");
    assert!(cortex_m3 > 100, "the Cortex-M3 panel has only {cortex_m3} coloured pixels: no points drawn?");
    assert!(cortex_m4f > 20, "the Cortex-M4F panel has only {cortex_m4f} coloured pixels: no point drawn?");
    assert!(cortex_m33 > 20, "the Cortex-M33 panel has only {cortex_m33} coloured pixels: no point drawn?");
}
