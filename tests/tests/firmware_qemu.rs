//! The firmware under QEMU renders exactly what the host renders. For both thesis scenes on the
//! boards (lm3s6965evb, Cortex-M3 with the OLED; mps2-an386, Cortex-M4F; mps2-an505, Cortex-M33;
//! snooker only on the microbit, a Cortex-M0 with 16 KB of RAM) in `f32`:
//! - `framebuffer.bin` equals, byte for byte, the host's in-process render of the same scene
//!   (parse, `fit_to_size(128, 64)`, prepare in `f32`, `render(.., Pga, Whole, ..)` into a `FrameBuffer`);
//! - the firmware counts the same work as the host (every render statistic): it builds the core
//!   with the same acceleration structures (`acceleration-tables`);
//! - on the lm3s6965evb, the OLED picture captured from QEMU (`oled.png`) is that framebuffer
//!   through the core's grey mapping (`microtrace::pixel::grey_level`, the LUT entry's luma);
//! - the lm3s6965evb builds stay within the memory budget of firmware/README.md;
//! - and in the integer number types too: the lattice in Q32.32 on the lm3s6965evb, snooker in
//!   Q32.32 on the microbit (no 32x32→64 multiply) and in `soft32` on the mps2-an386 equal the
//!   host's render in the same type;
//! - the linked-code audit (f64 routines, panic paths, formatting) agrees with `llvm-nm`.
//!
//! Each test builds the firmware (release, a few seconds) and runs it; xtask installs QEMU and
//! the rust targets when they are missing.

use std::path::PathBuf;
use std::process::Command;

use embedded_graphics::pixelcolor::GrayColor;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, Statistics, Whole, render};
use microtrace::model::SceneDescription;
use microtrace::scene::Scene;
// The budget of firmware/README.md for the lm3s6965evb (64 KB RAM, 256 KB flash): static RAM
// (the prepared scene with its acceleration structures: no framebuffer, no OLED copy, the rows
// streamed) plus peak stack leaves 40 KB of the RAM free.
use xtask::budget::{DATA_BYTES, FLASH_BYTES, FREE_RAM_BYTES, RAM_BYTES, STACK_BYTES, STATIC_RAM_BYTES};
use xtask::firmware::{self, Board, FirmwareOptions, FirmwareRun};

const WIDTH: u16 = 128;
const HEIGHT: u16 = 64;
const CAPACITY: usize = 64;

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes").join(name)
}

/// The host's render of the scene at the display's size, in `f32`.
fn host_render(name: &str) -> (SceneDescription<CAPACITY>, Vec<u8>, Statistics) {
    host_render_in::<f32>(name)
}

/// The host's render of the scene at the display's size, in the number type `N`.
fn host_render_in<N: microtrace::number::Number>(name: &str) -> (SceneDescription<CAPACITY>, Vec<u8>, Statistics) {
    let path = scene_path(name);
    let text = std::fs::read(&path).unwrap();
    let parsed: Result<SceneDescription<CAPACITY>, _> = microtrace::parser::parse_file(name, &text);
    let mut description = parsed.unwrap_or_else(|error| panic!("{}: {error}", path.display()));
    description.fit_to_size(WIDTH, HEIGHT);
    let scene = Scene::<N, CAPACITY>::prepare(&description).unwrap();
    let mut pixels = vec![0u8; WIDTH as usize * HEIGHT as usize];
    let mut frame = FrameBuffer::new(&mut pixels, WIDTH, HEIGHT).unwrap();
    let mut statistics = Statistics::default();
    render(&scene, Pga, Whole, &mut frame, &mut statistics);
    (description, pixels, statistics)
}

fn run_firmware(name: &str, board: Board) -> FirmwareRun {
    let stem = name.trim_end_matches(".mts");
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware").join(format!("{}-{stem}-f32", board.name()));
    let options = FirmwareOptions::new(scene_path(name), board, "f32", out);
    let run = firmware::run(&options).unwrap_or_else(|error| panic!("{name} on {}: {error}", board.name()));
    println!("{}", firmware::summary(&run, &options));
    run
}

fn firmware_matches_host(name: &str, board: Board) {
    let (description, expected, statistics) = host_render(name);
    let run = run_firmware(name, board);

    let framebuffer = std::fs::read(&run.framebuffer).unwrap();
    assert_eq!(framebuffer.len(), expected.len(), "{name} on {}: framebuffer size", board.name());
    let differing = framebuffer.iter().zip(&expected).filter(|(a, b)| a != b).count();
    assert!(differing == 0, "{name} on {}: {differing} of {} pixels differ from the host render", board.name(), expected.len());

    // The firmware counted the same work as the host: it has the same acceleration structures
    // (the core's `acceleration-tables`), sized by the scene.
    let numbers = &run.numbers;
    let counted = [
        ("pixels", statistics.pixels),
        ("rays_traced", statistics.rays_traced),
        ("rays_intersected", statistics.rays_intersected),
        ("ro_tests", statistics.ro_tests),
        ("ro_hits", statistics.ro_hits),
        ("shadow_rays", statistics.shadow_rays),
        ("shadow_tests", statistics.shadow_tests),
    ];
    for (key, host) in counted {
        assert_eq!(numbers[key], host, "{name} on {}: {key}, firmware against host", board.name());
    }
    // The grid is baked in flash, exactly its entries: they fit, with less than one spare entry
    // per object, and a scene that asks for the grid has it (an overflow would switch it off).
    let (entries, capacity, objects) = (numbers["grid_entries"], numbers["grid_capacity"], numbers["objects"]);
    assert!(entries <= capacity && capacity < entries + objects, "{name} on {}: grid pool of {capacity} for {entries} entries and {objects} objects", board.name());
    assert_eq!(entries > 0, description.optimizations.grid, "{name} on {}: the grid holds {entries} entries", board.name());
    // The count is the frame's, split at the render marker; `instructions` is the frame's too.
    let (frame, prepare, render) = (numbers["frame_instructions"], numbers["prepare_instructions"], numbers["render_instructions"]);
    assert!(prepare > 0 && render > 0, "{name} on {}: prepare {prepare}, render {render}", board.name());
    assert_eq!(prepare + render, frame, "{name} on {}: prepare + render against the frame", board.name());
    assert_eq!(numbers["instructions"], frame);
    assert_eq!(numbers["instructions_per_pixel"], frame / numbers["pixels"]);
    assert_eq!(numbers["frame_instructions_per_pixel"], frame / numbers["pixels"]);
    linked_code_is_clean(name, board, numbers);
    // The prepared scene is zero-initialised RAM: an initialised static would take its size
    // in flash as well (Scene::UNPREPARED, every byte zero).
    assert_eq!(numbers["data_bytes"], DATA_BYTES, "{name}: initialised statics (.data), which are also stored in flash");

    if let Some(oled_png) = &run.oled_png {
        let oled = xtask::oled::read_png(oled_png).unwrap();
        assert_eq!((oled.width, oled.height), (WIDTH as usize, HEIGHT as usize));
        let expected_greys: Vec<u8> =
            expected.iter().map(|index| microtrace::pixel::grey_level(&description.palette, *index).luma() * 17).collect();
        let differing = oled.pixels.iter().zip(&expected_greys).filter(|(a, b)| a != b).count();
        assert!(differing == 0, "{name}: {differing} OLED pixels differ from the framebuffer's luminance");
    }

    if board == Board::Lm3s6965evb {
        let within = |key: &str, budget: u64| {
            assert!(numbers[key] <= budget, "{name}: {key} = {} exceeds the budget of {budget}", numbers[key]);
        };
        within("flash_bytes", FLASH_BYTES);
        within("static_ram_bytes", STATIC_RAM_BYTES);
        within("stack_peak_bytes", STACK_BYTES);
        let used = numbers["static_ram_bytes"] + numbers["stack_peak_bytes"];
        assert!(used + FREE_RAM_BYTES <= RAM_BYTES, "{name}: {used} bytes of RAM used leave less than {FREE_RAM_BYTES} free");
    }
}

#[test]
fn snooker_on_lm3s6965evb_matches_the_host() {
    firmware_matches_host("snooker.mts", Board::Lm3s6965evb);
}

#[test]
fn lattice_on_lm3s6965evb_matches_the_host() {
    firmware_matches_host("lattice.mts", Board::Lm3s6965evb);
}

#[test]
fn snooker_on_mps2_an386_matches_the_host() {
    firmware_matches_host("snooker.mts", Board::Mps2An386);
}

#[test]
fn lattice_on_mps2_an386_matches_the_host() {
    firmware_matches_host("lattice.mts", Board::Mps2An386);
}

/// The board added by docs/architecture.md's "A new board" checklist alone: a Netduino Plus 2
/// (STM32F405, Cortex-M4F), snooker and the lattice the host's pictures byte for byte.
#[test]
fn snooker_and_the_lattice_on_netduinoplus2_match_the_host() {
    firmware_matches_host("snooker.mts", Board::Netduinoplus2);
    firmware_matches_host("lattice.mts", Board::Netduinoplus2);
}

#[test]
fn snooker_on_mps2_an505_matches_the_host() {
    firmware_matches_host("snooker.mts", Board::Mps2An505);
}

#[test]
fn lattice_on_mps2_an505_matches_the_host() {
    firmware_matches_host("lattice.mts", Board::Mps2An505);
}

/// The lattice does not fit the micro:bit's 16 KB in `f32` with the RAM check's reserve (the
/// firmware report lists what it needs); snooker does.
#[test]
fn snooker_on_microbit_matches_the_host() {
    firmware_matches_host("snooker.mts", Board::Microbit);
}

#[test]
fn a_bad_scene_fails_with_the_parsers_message() {
    let directory = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware");
    std::fs::create_dir_all(&directory).unwrap();
    let scene = directory.join("bad.mts");
    std::fs::write(&scene, "viewport 0 127 0 63\nsphere\n  scale 1 1\n").unwrap();
    let options = FirmwareOptions::new(&scene, Board::Lm3s6965evb, "f32", directory.join("bad-out"));
    let error = firmware::run(&options).unwrap_err();
    // The one format of scene errors (docs/bad-input.md): `FILE:line N: reason`.
    assert!(error.contains("bad.mts:line 3: "), "unexpected error: {error}");
}

/// The integer number types run the same core on the firmware: the framebuffer equals the
/// host's render in that type, byte for byte, and so do the statistics.
fn firmware_matches_host_in<N: microtrace::number::Number>(name: &str, board: Board) -> FirmwareRun {
    let (run, statistics) = firmware_picture_matches_host_in::<N>(name, board);
    assert_eq!(run.numbers["ro_tests"], statistics.ro_tests);
    assert_eq!(run.numbers["shadow_tests"], statistics.shadow_tests);
    run
}

/// [`firmware_matches_host_in`]'s picture and linked code, for a scene with an object that
/// reaches the eye plane: the chip's extents, made from bounds alone, give such an object the
/// whole screen where the host clips its silhouette at the eye plane
/// (`Acceleration::rebuild_from_bounds`), so the chip tests more (never fewer) objects.
fn firmware_picture_matches_host_in<N: microtrace::number::Number>(name: &str, board: Board) -> (FirmwareRun, Statistics) {
    let (_, expected, statistics) = host_render_in::<N>(name);
    let stem = name.trim_end_matches(".mts").trim_end_matches(".nff");
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware").join(format!("{}-{stem}-{}", board.name(), N::NAME));
    let options = FirmwareOptions::new(scene_path(name), board, N::NAME, out);
    let run = firmware::run(&options).unwrap_or_else(|error| panic!("{name} on {} in {}: {error}", board.name(), N::NAME));
    let framebuffer = std::fs::read(&run.framebuffer).unwrap();
    assert_eq!(framebuffer, expected, "{name} on {} in {}: the framebuffer differs from the host render", board.name(), N::NAME);
    assert!(run.numbers["ro_tests"] >= statistics.ro_tests, "{name}: the chip tested fewer objects than the host");
    linked_code_is_clean(name, board, &run.numbers);
    (run, statistics)
}

/// No f64 on the target and no panic path: a thesis-scene build in a number type other than
/// f64 links no double-precision routine (the scene reaches flash already in the number type,
/// `microtrace::bake`), no `core::panicking` symbol and no `core::fmt` code (indices in
/// range by construction). The ELF audit is `xtask::elf`'s, which
/// `the_linked_audit_agrees_with_llvm_nm` checks against llvm-nm; the names are in the run's
/// linked-audit.txt.
fn linked_code_is_clean(name: &str, board: Board, numbers: &std::collections::BTreeMap<String, u64>) {
    for key in ["f64_symbols", "panic_symbols", "fmt_symbols"] {
        assert_eq!(numbers[key], 0, "{name} on {}: {key} (see linked-audit.txt)", board.name());
    }
    // And the stack never reached the end of its region (a 4 KB margin; 256 bytes on the 8 KB
    // lm3s811evb, whose whole stack is 3.4 KB): an overflow would run into the statics.
    let (peak, size) = (numbers["stack_peak_bytes"], numbers["stack_size_bytes"]);
    let margin = if board == Board::Lm3s811evb { 256 } else { 4096 };
    assert!(peak + margin <= size, "{name} on {}: peak stack {peak} of the {size} bytes there are", board.name());
}

/// The ray tree on the firmware (chapter 5): the polished snooker scene, built with the
/// `ray-tree` feature the scene asks for, renders the host's image byte for byte with the same
/// secondary rays, on both boards.
fn ray_tree_matches_the_host(board: Board) {
    let name = "snooker-polished.mts";
    let (_, expected, statistics) = host_render_in::<f32>(name);
    assert!(statistics.secondary_rays_total() > 0);
    let run = run_firmware(name, board);
    let framebuffer = std::fs::read(&run.framebuffer).unwrap();
    let differing = framebuffer.iter().zip(&expected).filter(|(a, b)| a != b).count();
    assert_eq!(differing, 0, "{name} on {}: {differing} pixels differ from the host render", board.name());
    for (key, host) in [("secondary_rays", statistics.secondary_rays_total()), ("secondary_tests", statistics.secondary_tests), ("shadow_tests", statistics.shadow_tests)] {
        assert_eq!(run.numbers[key], host, "{name} on {}: {key}", board.name());
    }
    linked_code_is_clean(name, board, &run.numbers);
    assert!(links_the_ray_tree(&run.elf), "{name} on {}: the ray tree is not linked", board.name());
}

/// Whether the firmware links the ray tree's walk (`render::ray_tree::trace_tree`).
fn links_the_ray_tree(elf: &std::path::Path) -> bool {
    let names = xtask::elf::symbol_names(&std::fs::read(elf).unwrap()).unwrap();
    names.iter().any(|name| name.contains("microtrace::render::ray_tree::trace_tree"))
}

/// Whether the firmware links antialiasing's code (`render::antialias`).
fn links_antialiasing(elf: &std::path::Path) -> bool {
    let names = xtask::elf::symbol_names(&std::fs::read(elf).unwrap()).unwrap();
    names.iter().any(|name| name.contains("microtrace::render::antialias::"))
}

/// Only what the scene needs: a build for a scene without reflective or transparent objects and
/// without antialiasing (the thesis's snooker) links none of the ray tree and none of the
/// antialiasing.
#[test]
fn a_scene_without_mirrors_links_no_ray_tree() {
    let run = run_firmware("snooker.mts", Board::Mps2An386);
    assert!(!links_the_ray_tree(&run.elf), "snooker links the ray tree");
    assert!(!links_antialiasing(&run.elf), "snooker links antialiasing");
    let names = xtask::elf::symbol_names(&std::fs::read(&run.elf).unwrap()).unwrap();
    assert!(!names.iter().any(|name| name.contains("nearest_secondary_hit") || name.contains("space_grid")), "snooker links secondary rays' code");
}

/// Antialiasing on the firmware (chapter 5): the antialiased lattice renders the host's image
/// byte for byte, with the same rays.
#[test]
fn antialiasing_on_mps2_an386_matches_the_host() {
    let name = "lattice-antialiased.mts";
    let (_, expected, statistics) = host_render_in::<f32>(name);
    let run = run_firmware(name, Board::Mps2An386);
    let framebuffer = std::fs::read(&run.framebuffer).unwrap();
    assert_eq!(framebuffer, expected, "{name}: the framebuffer differs from the host render");
    assert_eq!(run.numbers["rays_traced"], statistics.rays_traced);
    assert!(statistics.rays_traced > 2 * statistics.pixels, "{} rays for {} pixels", statistics.rays_traced, statistics.pixels);
    linked_code_is_clean(name, Board::Mps2An386, &run.numbers);
    assert!(links_antialiasing(&run.elf), "{name}: antialiasing is not linked");
}

#[test]
fn the_ray_tree_on_lm3s6965evb_matches_the_host() {
    ray_tree_matches_the_host(Board::Lm3s6965evb);
}

#[test]
fn the_ray_tree_on_mps2_an386_matches_the_host() {
    ray_tree_matches_the_host(Board::Mps2An386);
}

#[test]
fn lattice_in_fixed_point_on_lm3s6965evb_matches_the_host() {
    firmware_matches_host_in::<microtrace::number::Fixed>("lattice.mts", Board::Lm3s6965evb);
}

/// A scene with code of its own on the chip, in `f32` on the M4F: the host's picture and counts,
/// and the modules named linked only there (snooker links none of them).
fn links_only_where_used(name: &str, modules: &[&str]) {
    let run = run_firmware(name, Board::Mps2An386);
    let (_, expected, statistics) = host_render(name);
    let framebuffer = std::fs::read(&run.framebuffer).unwrap();
    assert_eq!(framebuffer, expected, "{name}: the framebuffer differs from the host render");
    assert_eq!(run.numbers["ro_tests"], statistics.ro_tests);
    assert_eq!(run.numbers["shadow_tests"], statistics.shadow_tests);
    linked_code_is_clean(name, Board::Mps2An386, &run.numbers);
    assert!(links(&run.elf, modules), "{name}: none of {modules:?} is linked");
    assert!(!links(&run_firmware("snooker.mts", Board::Mps2An386).elf, modules), "snooker links one of {modules:?}");
}

fn links(elf: &std::path::Path, modules: &[&str]) -> bool {
    let names = xtask::elf::symbol_names(&std::fs::read(elf).unwrap()).unwrap();
    names.iter().any(|name| modules.iter().any(|module| name.contains(module)))
}

/// The disc (scenes/disc.mts; the primitive added by docs/architecture.md's checklist) on the
/// chip: the host's picture in `f32` on the M4F and in `soft32` on the M3, the tilted disc seen
/// almost edge-on included.
#[test]
fn the_disc_on_mps2_an386_and_lm3s6965evb_matches_the_host() {
    firmware_matches_host("disc.mts", Board::Mps2An386);
    firmware_matches_host_in::<microtrace::number::SoftFloat>("disc.mts", Board::Lm3s6965evb);
}

/// The ring torus (scenes/torus.mts) on the chip: the host's picture in `f32` on the M4F and in
/// `soft32` on the M3, and its intersection linked only there.
#[test]
fn the_torus_on_mps2_an386_matches_the_host() {
    links_only_where_used("torus.mts", &["shapes::torus", "shapes::polynomial"]);
}

#[test]
fn the_torus_in_soft32_on_lm3s6965evb_matches_the_host() {
    firmware_matches_host_in::<microtrace::number::SoftFloat>("torus.mts", Board::Lm3s6965evb);
}

/// Solids (issue 23, constructive solid geometry) on the chip: the die (a cube ∩ a sphere minus
/// six pips) renders the host's picture in `f32` on both boards and in `soft32` on the M3, the
/// cup (a torus handle in a solid) in `soft32` on the M4F, the glass lens (sphere ∩ sphere,
/// refracting) in `f32` on the M4F and the nut (a hexagonal prism minus a cylinder) in `soft32`
/// on the M3; the walk of solids is linked only where the scene has one.
#[test]
fn the_die_on_mps2_an386_matches_the_host() {
    links_only_where_used("csg/die.mts", &["csg::solid", "csg::spans"]);
}

#[test]
fn the_die_on_lm3s6965evb_matches_the_host_in_f32_and_soft32() {
    firmware_matches_host_in::<f32>("csg/die.mts", Board::Lm3s6965evb);
    firmware_matches_host_in::<microtrace::number::SoftFloat>("csg/die.mts", Board::Lm3s6965evb);
}

#[test]
fn the_cup_in_soft32_on_mps2_an386_matches_the_host() {
    firmware_matches_host_in::<microtrace::number::SoftFloat>("csg/cup.mts", Board::Mps2An386);
}

#[test]
fn the_glass_lens_on_mps2_an386_matches_the_host() {
    // Its floor reaches the eye plane: the picture is the host's, the counts are not.
    let (run, statistics) = firmware_picture_matches_host_in::<f32>("csg/lens.mts", Board::Mps2An386);
    assert!(statistics.secondary_rays_total() > 0, "the lens traced no secondary ray");
    assert_eq!(run.numbers["secondary_rays"], statistics.secondary_rays_total());
}

/// Haines' NFF on the chip (issue 24): the SPD's tree at its smallest (15 spheres, 15 open
/// frusta, the ground square as two triangles, 7 lights, read by the same NFF reader at build
/// time) renders the host's picture in `f32` on the M4F and in `soft32` on the M3.
#[test]
fn the_spd_tree_from_nff_on_mps2_an386_and_lm3s6965evb_matches_the_host() {
    // Its ground square reaches the eye plane: the picture is the host's, the counts are not
    // (the chip's extents, from bounds alone, give the ground the whole screen).
    firmware_picture_matches_host_in::<f32>("spd/tree3.nff", Board::Mps2An386);
    firmware_picture_matches_host_in::<microtrace::number::SoftFloat>("spd/tree3.nff", Board::Lm3s6965evb);
}

/// A scene of more objects than the blocker sets hold (Haines' tree at size 6: 256 objects, 7
/// lights) gets its hierarchy of boxes made at build time and kept in flash (the chip has no
/// `f64` to build one; `optimize::baked_hierarchy`): it walks it for its shadow and secondary
/// rays, needs no per-object shadow tables on the stack, and so fits the Cortex-M4F's 64 KB
/// (it needed 157,840 bytes without), rendering the host's picture, which the host made without
/// a hierarchy.
#[test]
fn the_spd_tree_of_256_objects_walks_a_hierarchy_in_flash_on_mps2_an386() {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware").join("mps2-an386-tree-s6-f32");
    std::fs::create_dir_all(&out).unwrap();
    let scene = xtask::spd_report::decompressed(&scene_path("spd/full/tree-s6.nff.gz"), &out.join("tree-s6.nff")).unwrap();
    let options = FirmwareOptions::new(&scene, Board::Mps2An386, "f32", out.clone());
    let run = firmware::run(&options).unwrap_or_else(|error| panic!("tree-s6 on mps2-an386: {error}"));
    println!("{}", firmware::summary(&run, &options));
    assert_eq!(xtask::report::differing_from_host(&run, &scene, "f32", "scene").unwrap(), 0, "tree-s6: pixels differ from the host's render");
    linked_code_is_clean("tree-s6", Board::Mps2An386, &run.numbers);
    // The hierarchy is in flash: its nodes (32 bytes each in f32) and its leaves' objects.
    let elf = std::fs::read(&run.elf).unwrap();
    let (symbols, _) = xtask::elf::flash_symbols(&elf).unwrap();
    let bytes = |name: &str| symbols.iter().find(|symbol| symbol.demangled.ends_with(name)).map(|symbol| symbol.bytes);
    let nodes = bytes("::HIERARCHY_NODES").expect("tree-s6: no hierarchy's nodes in flash");
    let order = bytes("::HIERARCHY_ORDER").expect("tree-s6: no hierarchy's order in flash");
    assert!(nodes >= 32 * 64 && nodes % 32 == 0, "tree-s6: {nodes} bytes of nodes");
    assert!(order >= 2 * 256, "tree-s6: {order} bytes of the leaves' objects for 256 objects");
}

#[test]
fn the_nut_in_soft32_on_lm3s6965evb_matches_the_host() {
    firmware_matches_host_in::<microtrace::number::SoftFloat>("csg/nut.mts", Board::Lm3s6965evb);
}

/// The smallest board (issue 25, "The smallest chips"): the lm3s811evb, a Cortex-M3 with 64 KB
/// of flash and 8 KB of RAM, renders snooker at 128x64 in `f32` (a type that meets fixed's
/// accuracy targets: tests/tests/thesis_scenes.rs), streamed to the host, the host's picture
/// byte for byte, within its memory as the build measured it.
#[test]
fn snooker_fits_the_lm3s811evb() {
    let run = fits_the_lm3s811evb("snooker.mts");
    // The light's shadow tables were made at build time (the view and the light are fixed
    // there): they are in flash, one cone and one blocker set an object, and the code that
    // builds them is not linked.
    let elf = std::fs::read(&run.elf).unwrap();
    let (symbols, _) = xtask::elf::flash_symbols(&elf).unwrap();
    let bytes = |name: &str| symbols.iter().find(|symbol| symbol.demangled.ends_with(name)).map(|symbol| symbol.bytes);
    let cones = bytes("::SHADOW_CONES_0").expect("snooker: no light cones in flash");
    let blockers = bytes("::SHADOW_BLOCKERS_0").expect("snooker: no blocker sets in flash");
    let cone = std::mem::size_of::<microtrace::optimize::shadow_culling::DirectionChord<f32>>();
    let set = std::mem::size_of::<microtrace::optimize::shadow_culling::BlockerSet>();
    let objects = microtrace::parser::parse::<64>(&std::fs::read(scene_path("snooker.mts")).unwrap()).unwrap().objects.len();
    assert_eq!((cones, blockers), ((objects * cone) as u64, (objects * set) as u64), "snooker: the shadow tables in flash are not one cone and one set for each of its {objects} objects");
    assert!(!symbols.iter().any(|symbol| symbol.demangled.contains("build_shadow_tables")), "snooker: the shadow tables' building code is linked");
    // So were the tables that depend on the view: each object's eye (12 bytes in f32), extent
    // (16) and the test order (2) are in flash, and nothing that builds them is linked (the
    // capsules seen from the eye, `ScreenMap`).
    for (table, each) in [("::VIEW_EYES", 12), ("::VIEW_EXTENTS", 16), ("::VIEW_ORDER", 2)] {
        assert_eq!(bytes(table), Some((objects * each) as u64), "snooker: {table} is not {each} bytes for each of its {objects} objects in flash");
    }
    assert!(!symbols.iter().any(|symbol| symbol.demangled.contains("ScreenMap")), "snooker: the view's building code is linked");
}

/// The lattice (54 objects) fits the lm3s811evb too, now that nothing on its stack grows with
/// the objects (the shadow tables and the screen grid in flash): the host's picture, byte for
/// byte, within the board's RAM and flash.
#[test]
fn the_lattice_fits_the_lm3s811evb() {
    fits_the_lm3s811evb("lattice.mts");
}

/// `name` rendered at 128x64 in `f32` on the lm3s811evb, the host's picture and counts, within
/// its 8 KB of RAM (static and peak stack, as the build measured them) and 64 KB of flash.
fn fits_the_lm3s811evb(name: &str) -> FirmwareRun {
    let run = firmware_matches_host_in::<f32>(name, Board::Lm3s811evb);
    let (ram, stack, flash) = (run.numbers["static_ram_bytes"], run.numbers["stack_peak_bytes"], run.numbers["flash_bytes"]);
    assert!(ram + stack <= 8 * 1024, "{name} on the lm3s811evb: {ram} bytes of static RAM and {stack} of peak stack exceed its 8,192");
    assert!(flash <= 64 * 1024, "{name} on the lm3s811evb: {flash} bytes of flash exceed its 65,536");
    run
}

/// The smallest board's own display (issue 25, target 1): snooker rendered at the panel's 96x16
/// on the lm3s811evb, streamed to the host as the host renders it, and shown on its SSD0303 OLED
/// (I2C) as the dots the host's error diffusion makes of the same picture (each entry's luma,
/// Floyd–Steinberg, one row of errors: the 1-bit path of `microtrace render --display ssd1306`),
/// read back from QEMU's screen; all within its 8 KB of RAM.
#[test]
fn snooker_shows_on_the_lm3s811evb_oled() {
    shows_on_the_lm3s811evb_oled("snooker.mts");
}

/// The lattice (54 objects) on the OLED too, now that every table of the view is in flash.
#[test]
fn the_lattice_shows_on_the_lm3s811evb_oled() {
    shows_on_the_lm3s811evb_oled("lattice.mts");
}

fn shows_on_the_lm3s811evb_oled(name: &str) {
    let size = xtask::firmware::LM3S811EVB_OLED;
    let path = scene_path(name);
    let text = std::fs::read(&path).unwrap();
    let parsed: Result<SceneDescription<CAPACITY>, _> = microtrace::parser::parse_file(name, &text);
    let mut description = parsed.unwrap();
    description.fit_to_size(size.0, size.1);
    let scene = Scene::<f32, CAPACITY>::prepare(&description).unwrap();
    let mut expected = vec![0u8; usize::from(size.0) * usize::from(size.1)];
    let mut frame = FrameBuffer::new(&mut expected, size.0, size.1).unwrap();
    render(&scene, Pga, Whole, &mut frame, &mut Statistics::default());
    let dots = one_bit_dots(&expected, size, &description.palette);

    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware").join(format!("lm3s811evb-{}-96x16-f32", name.trim_end_matches(".mts")));
    let mut options = FirmwareOptions::new(path, Board::Lm3s811evb, "f32", out);
    options.size = size;
    let run = firmware::run(&options).unwrap_or_else(|error| panic!("{name} at 96x16 on the lm3s811evb: {error}"));
    println!("{}", firmware::summary(&run, &options));
    assert_eq!(std::fs::read(&run.framebuffer).unwrap(), expected, "{name} at 96x16 on the lm3s811evb: the framebuffer differs from the host render");
    let oled = xtask::oled::read_png(run.oled_png.as_ref().expect("the lm3s811evb's OLED was not captured")).unwrap();
    assert_eq!((oled.width, oled.height), (usize::from(size.0), usize::from(size.1)));
    let shown: Vec<bool> = oled.pixels.iter().map(|grey| *grey == 255).collect();
    assert!(oled.pixels.iter().all(|grey| *grey == 0 || *grey == 255), "the OLED shows only black and white dots");
    let differing = shown.iter().zip(&dots).filter(|(a, b)| a != b).count();
    assert_eq!(differing, 0, "{name}: {differing} of the OLED's dots differ from the host's error diffusion");
    assert!(dots.iter().any(|dot| *dot) && dots.iter().any(|dot| !*dot), "a picture of dots, not a blank screen");
    linked_code_is_clean(&format!("{name} at 96x16"), Board::Lm3s811evb, &run.numbers);
    let (ram, stack) = (run.numbers["static_ram_bytes"], run.numbers["stack_peak_bytes"]);
    assert!(ram + stack <= 8 * 1024, "{name} at 96x16 with the OLED: {ram} bytes of static RAM and {stack} of peak stack exceed 8,192");
}

/// The dots of the core's error diffusion over each palette entry's luma, row by row as the
/// streamed render sends them to a 1-bit display.
fn one_bit_dots(indices: &[u8], (width, height): (u16, u16), palette: &microtrace::model::Palette) -> Vec<bool> {
    use embedded_graphics::pixelcolor::BinaryColor;
    use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Point, Size};
    use embedded_graphics::primitives::Rectangle;
    use microtrace::pixel::{ColourMap, ErrorDiffusion, LutLuma};

    struct Dots {
        size: (u16, u16),
        lit: Vec<bool>,
    }
    impl OriginDimensions for Dots {
        fn size(&self) -> Size {
            Size::new(u32::from(self.size.0), u32::from(self.size.1))
        }
    }
    impl DrawTarget for Dots {
        type Color = BinaryColor;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = embedded_graphics::Pixel<BinaryColor>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
            for embedded_graphics::Pixel(point, colour) in pixels {
                self.lit[point.y as usize * usize::from(self.size.0) + point.x as usize] = colour.is_on();
            }
            Ok(())
        }
    }
    let luma = LutLuma::new(palette);
    let mut diffusion = ErrorDiffusion::<_, 96>::new(Dots { size: (width, height), lit: vec![false; indices.len()] });
    for (y, row) in indices.chunks(usize::from(width)).enumerate() {
        let area = Rectangle::new(Point::new(0, y as i32), Size::new(u32::from(width), 1));
        diffusion.fill_contiguous(&area, row.iter().map(|index| luma.colour(*index))).unwrap();
    }
    diffusion.into_inner().lit
}

#[test]
fn snooker_in_fixed_point_on_microbit_matches_the_host() {
    firmware_matches_host_in::<microtrace::number::Fixed>("snooker.mts", Board::Microbit);
}

#[test]
fn snooker_in_soft32_on_mps2_an386_matches_the_host() {
    firmware_matches_host_in::<microtrace::number::SoftFloat>("snooker.mts", Board::Mps2An386);
}

/// The firmware models only the primitives its features enable: building a scene of spheres
/// without the `sphere` feature fails in build.rs, saying so.
#[test]
fn a_scene_needing_a_primitive_left_out_does_not_build() {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware/no-sphere");
    let options = FirmwareOptions::new(scene_path("snooker.mts"), Board::Lm3s6965evb, "f32", out);
    let error = firmware::build_with_primitives(&options, &["cube"]).unwrap_err();
    assert!(error.contains("without the `sphere` feature"), "unexpected error: {error}");
}

/// The instruction counts (the QEMU plugin's: frame, prepare, render) are the same run to run.
#[test]
fn the_instruction_count_is_deterministic() {
    let counts: Vec<[u64; 3]> = (0..2)
        .map(|attempt| {
            let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("firmware/repeat-{attempt}"));
            let options = FirmwareOptions::new(scene_path("snooker.mts"), Board::Mps2An386, "f32", out);
            let numbers = firmware::run(&options).unwrap_or_else(|error| panic!("{error}")).numbers;
            ["frame_instructions", "prepare_instructions", "render_instructions"].map(|key| numbers[key])
        })
        .collect();
    assert_eq!(counts[0], counts[1]);
}

/// `llvm-nm`: the toolchain's, else the one on the PATH.
fn llvm_nm() -> PathBuf {
    xtask::setup::llvm_tool("llvm-nm")
}

/// The audit finds the double-precision routines the mps2-an386 `f32` snooker build really links
/// (today it links some: `f64` scene preparation and libm), checked against `llvm-nm`'s own
/// list rather than a count, so it holds as that code is removed: every symbol the audit names
/// is in the ELF, and every `__aeabi_d*` (and `__aeabi_*2d`) helper `llvm-nm` lists is among the
/// audit's f64 routines. report.json and linked-audit.txt carry the same.
#[test]
fn the_linked_audit_agrees_with_llvm_nm() {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware/audit-mps2-an386-snooker-f32");
    let options = FirmwareOptions::new(scene_path("snooker.mts"), Board::Mps2An386, "f32", out);
    let run = firmware::run(&options).unwrap_or_else(|error| panic!("{error}"));
    let nm = llvm_nm();
    let output = Command::new(&nm)
        .arg("--defined-only")
        .arg(&run.elf)
        .output()
        .unwrap_or_else(|error| panic!("cannot run {} (scripts/setup.sh adds llvm-tools): {error}", nm.display()));
    assert!(output.status.success(), "{}: {}", nm.display(), String::from_utf8_lossy(&output.stderr));
    // `ADDRESS TYPE NAME` a line.
    let listed: Vec<String> = String::from_utf8_lossy(&output.stdout)
        .lines()
        .filter_map(|line| line.split_whitespace().nth(2).map(str::to_owned))
        .collect();
    assert!(listed.iter().any(|name| name == "microtrace_measure_start"), "llvm-nm listed no firmware symbols");

    let audit = &run.audit;
    for symbol in audit.f64.iter().chain(&audit.panic).chain(&audit.fmt) {
        assert!(listed.contains(&symbol.name), "the audit names {} ({}), which llvm-nm does not list", symbol.name, symbol.demangled);
    }
    // The ARM run-time ABI's double helpers, `__aeabi_d*` (not `__aeabi_div0`, the integer
    // divide-by-zero hook) and the conversions to double, `__aeabi_*2d`.
    let aeabi_double: Vec<&String> = listed
        .iter()
        .filter(|name| (name.starts_with("__aeabi_d") && !name.starts_with("__aeabi_div")) || (name.starts_with("__aeabi_") && name.ends_with("2d")))
        .collect();
    for name in &aeabi_double {
        assert!(audit.f64.iter().any(|symbol| &symbol.name == *name), "llvm-nm lists {name}, the audit's f64 routines lack it");
    }
    println!("llvm-nm lists {} __aeabi_ double helpers; the audit has {} f64 routines", aeabi_double.len(), audit.f64.len());

    for (key, symbols) in [("f64_symbols", &audit.f64), ("panic_symbols", &audit.panic), ("fmt_symbols", &audit.fmt)] {
        assert_eq!(run.numbers[key], symbols.len() as u64, "report.json's {key}");
    }
    let text = std::fs::read_to_string(&run.linked_audit_txt).unwrap();
    for symbol in audit.f64.iter().chain(&audit.panic).chain(&audit.fmt) {
        assert!(text.contains(&symbol.demangled), "linked-audit.txt lacks {}", symbol.demangled);
    }
}

/// The firmware's progressive build (`cargo xtask firmware --progressive`) ends with the host's
/// normal render, in the framebuffer and on the OLED, with the same statistics; its report says
/// how many rays each pass traced, and they add up to the whole render's.
#[test]
fn progressive_firmware_on_lm3s6965evb_ends_with_the_host_image() {
    let (description, expected, statistics) = host_render("snooker.mts");
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("firmware/lm3s6965evb-snooker-f32-progressive");
    let mut options = FirmwareOptions::new(scene_path("snooker.mts"), Board::Lm3s6965evb, "f32", out);
    options.progressive = true;
    let run = firmware::run(&options).unwrap_or_else(|error| panic!("progressive snooker: {error}"));
    println!("{}", firmware::summary(&run, &options));
    assert_eq!(std::fs::read(&run.framebuffer).unwrap(), expected, "the progressive framebuffer differs from the host render");
    let numbers = &run.numbers;
    assert_eq!(numbers["pixels"], statistics.pixels);
    assert_eq!(numbers["rays_traced"], statistics.rays_traced);
    assert_eq!(numbers["rays_intersected"], statistics.rays_intersected);
    let passes = ["pass1_rays_traced", "pass2_rays_traced", "pass3_rays_traced", "pass4_rays_traced"].map(|key| numbers[key]);
    assert_eq!(passes.iter().sum::<u64>(), statistics.rays_traced, "{passes:?}");
    assert!(passes[0] > 0 && passes[0] * 8 < passes[3], "{passes:?}");
    linked_code_is_clean("snooker.mts progressive", Board::Lm3s6965evb, numbers);
    let oled = xtask::oled::read_png(run.oled_png.as_ref().unwrap()).unwrap();
    let expected_greys: Vec<u8> = expected.iter().map(|index| microtrace::pixel::grey_level(&description.palette, *index).luma() * 17).collect();
    assert!(oled.pixels == expected_greys, "the OLED after the progressive render differs from the framebuffer's luminance");
}
