extern crate std;

use crate::model::{SceneError, SceneErrorKind, TOKEN_EXCERPT_BYTES, Token};
use std::string::{String, ToString};
use std::vec::Vec;

use super::*;
use crate::model::{Light, Material, Optimizations, Primitive, Projection, SceneDescription, Viewport, Window};
use crate::model::{Palette, Rgb4};

type Scene = SceneDescription<512>;

const SNOOKER: &[u8] = include_bytes!("../../../scenes/snooker.mts");
const LATTICE: &[u8] = include_bytes!("../../../scenes/lattice.mts");

fn ok(text: &str) -> SceneDescription<64> {
    parse::<64>(text.as_bytes()).unwrap_or_else(|error| panic!("{text:?}: {error}"))
}

fn err(text: &str) -> SceneError {
    err_bytes(text.as_bytes())
}

fn err_bytes(text: &[u8]) -> SceneError {
    match parse::<64>(text) {
        Ok(_) => panic!("{:?} parsed without error", String::from_utf8_lossy(text)),
        Err(error) => error,
    }
}

/// Asserts the error's line and that its message contains every one of `parts`.
fn check(text: &str, line: u32, parts: &[&str]) -> SceneErrorKind {
    let error = err(text);
    let message = error.to_string();
    assert_eq!(error.line, line, "{text:?}: {message}");
    assert!(message.starts_with(&std::format!("line {line}: ")), "{message}");
    for part in parts {
        assert!(message.contains(part), "{text:?}: message {message:?} lacks {part:?}");
    }
    error.kind
}

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9)
}

// ---------------------------------------------------------------- the thesis scenes

#[test]
fn snooker_parses() {
    let scene: Scene = parse(SNOOKER).unwrap();
    assert_eq!(scene.objects.len(), 21);
    assert!(scene.objects.iter().all(|o| o.primitive == Primitive::Sphere));
    assert_eq!(scene.viewport, Viewport { x1: 0, x2: 527, y1: 0, y2: 479 });
    assert_eq!(scene.window, Window { x1: -50.845, x2: 50.845, y1: 124.9296, y2: 217.3575 });
    assert_eq!(scene.view_plane, 1280.0);
    assert_eq!(scene.projection, Projection::Perspective { eye: [0.0, 220.0, 1380.0] });
    assert_eq!(scene.light, Light::Point([300.0, 1400.0, 900.0]));
    assert_eq!(scene.ambient, 0.2);
    assert!(scene.shadows);
    assert!(!scene.dither);
    assert_eq!(scene.background, 120);
    assert_eq!(scene.optimizations, Optimizations::ALL);
    // group 1 15 1 1 up: shade 15 is the cell, shade 0 black.
    assert_eq!(scene.palette.entry(31), Rgb4::new(15, 1, 1));
    assert_eq!(scene.palette.entry(16), Rgb4::new(0, 0, 0));
    // group 2 15 14 0 up
    assert_eq!(scene.palette.entry(47), Rgb4::new(15, 14, 0));
    // group 9 was never loaded: the grey ramp.
    assert_eq!(scene.palette.entry(9 * 16 + 5), Rgb4::new(5, 5, 5));
    let first = &scene.objects[0];
    assert_eq!(first.line, 29);
    assert_eq!(first.material.colour, 1);
    assert_eq!((first.material.ka, first.material.kd, first.material.ks), (1.0, 0.6, 0.35));
    assert_eq!((first.material.pwr, first.material.rnd), (40.0, 0.3));
    // scale 26.25 then translate 0 26.25 945.75: the centre goes to the translation, the top
    // of the ball 26.25 above it.
    assert!(close(first.world_from_object.transform_point([0.0, 0.0, 0.0]), [0.0, 26.25, 945.75]));
    assert!(close(first.world_from_object.transform_point([0.0, 1.0, 0.0]), [0.0, 52.5, 945.75]));
    let mut expected = Palette::grey();
    expected.set_group_up(7, Rgb4::new(2, 10, 3));
    assert_eq!(scene.palette.entry(7 * 16 + 8), expected.entry(7 * 16 + 8));
}

#[test]
fn lattice_parses() {
    let scene: Scene = parse(LATTICE).unwrap();
    assert_eq!(scene.objects.len(), 54);
    let spheres = scene.objects.iter().filter(|o| o.primitive == Primitive::Sphere).count();
    let cylinders = scene.objects.iter().filter(|o| o.primitive == Primitive::Cylinder).count();
    assert_eq!((spheres, cylinders), (27, 27));
    assert_eq!(scene.viewport, Viewport { x1: 0, x2: 465, y1: 0, y2: 479 });
    assert_eq!(scene.window, Window { x1: -41.9467, x2: 48.4416, y1: 205.0303, y2: 298.1399 });
    assert_eq!(scene.view_plane, 500.0);
    assert_eq!(scene.projection, Projection::Perspective { eye: [0.0, 340.0, 650.0] });
    assert_eq!(scene.light, Light::Point([-300.0, 800.0, 700.0]));
    assert_eq!(scene.background, 115);
    assert_eq!(scene.palette.entry(47), Rgb4::new(3, 9, 15));
    assert_eq!(scene.palette.entry(16 + 15), Rgb4::new(15, 2, 2));
    // Every object is invertible, and lines increase.
    assert!(scene.objects.iter().all(|o| o.world_from_object.affine_inverse().is_some()));
    assert!(scene.objects.windows(2).all(|w| w[0].line < w[1].line));
    // The first sphere: scale 22, translate (-100,-100,-100), rotate y 20.
    let mut m = crate::geometry::Matrix4::IDENTITY;
    m.scale([22.0; 3]);
    m.translate([-100.0; 3]);
    m.rotate(1, 20.0);
    assert_eq!(scene.objects[0].world_from_object, m);
}

#[test]
fn thesis_scenes_with_crlf_line_endings_parse_identically() {
    for source in [SNOOKER, LATTICE] {
        let crlf: Vec<u8> = source.iter().flat_map(|&b| if b == b'\n' { std::vec![b'\r', b'\n'] } else { std::vec![b] }).collect();
        let a: Scene = parse(source).unwrap();
        let b: Scene = parse(&crlf).unwrap();
        assert_eq!(a, b);
    }
}

// ---------------------------------------------------------------- the spec's example and defaults

#[test]
fn spec_example() {
    let text = "viewport 0 127 0 63\nwindow -2 2 -1 1\nviewplane 4\nperspective 0 0 10\nlight point 4 6 12\n\
                ambient 0.2\nshadows on\ngroup 1 15 3 3 up\nsphere\n  translate 0 0 -2\n  colour 1\n  kd 0.5\n  ks 0.5\n  pwr 20\n";
    let scene = ok(text);
    assert_eq!(scene.viewport, Viewport { x1: 0, x2: 127, y1: 0, y2: 63 });
    assert_eq!((scene.viewport.width(), scene.viewport.height()), (128, 64));
    assert_eq!(scene.window, Window { x1: -2.0, x2: 2.0, y1: -1.0, y2: 1.0 });
    assert_eq!(scene.view_plane, 4.0);
    assert_eq!(scene.projection, Projection::Perspective { eye: [0.0, 0.0, 10.0] });
    assert_eq!(scene.light, Light::Point([4.0, 6.0, 12.0]));
    assert_eq!(scene.ambient, 0.2);
    assert!(scene.shadows);
    assert_eq!(scene.palette.entry(31), Rgb4::new(15, 3, 3));
    assert_eq!(scene.objects.len(), 1);
    let sphere = &scene.objects[0];
    assert_eq!((sphere.primitive, sphere.line), (Primitive::Sphere, 9));
    assert_eq!(sphere.material, Material { colour: 1, kd: 0.5, ks: 0.5, pwr: 20.0, ..Material::default() });
    assert!(close(sphere.world_from_object.transform_point([0.0, 0.0, 1.0]), [0.0, 0.0, -1.0]));
}

#[test]
fn empty_and_comment_only_inputs_give_the_defaults() {
    let defaults = SceneDescription::<64>::default();
    for text in ["", "\n", "   \t \n\n", "# nothing\n  # more # and more\n", "\r\n\r\n", "\u{feff}# bom\n"] {
        assert_eq!(ok(text), defaults, "{text:?}");
    }
    let scene = ok("");
    assert_eq!(scene.viewport, Viewport { x1: 0, x2: 639, y1: 0, y2: 479 });
    assert_eq!(scene.window, Window { x1: -100.0, x2: 100.0, y1: -100.0, y2: 100.0 });
    assert_eq!(scene.view_plane, 500.0);
    assert_eq!(scene.projection, Projection::Parallel { direction: [0.0, 0.0, -1.0] });
    assert_eq!(scene.light, Light::Direction([1.0, 1.0, 1.0]));
    assert_eq!(scene.ambient, 0.2);
    assert_eq!(scene.background, 113);
    assert!(!scene.shadows && !scene.dither);
    assert_eq!(scene.optimizations, Optimizations::ALL);
    assert_eq!(scene.palette, Palette::grey());
    assert!(scene.objects.is_empty());
}

#[test]
fn a_torus_takes_its_tube_radius_to_the_nearest_step() {
    let scene = ok("torus 0.25\ntorus 0.3\n  scale 2 2 2");
    assert_eq!(scene.objects[0].primitive, Primitive::Torus(crate::model::Tube::QUARTER));
    let Primitive::Torus(tube) = scene.objects[1].primitive else { panic!("{:?}", scene.objects[1].primitive) };
    // 0.3 is 9830.4 steps of 2^-15: 9830.
    assert_eq!(tube.steps(), 9830);
    assert!((tube.to_f64() - 0.3).abs() <= 0.5 / 32768.0);
    assert_eq!(tube.radius::<f32>(), (9830.0 / 32768.0) as f32);
    // A ring torus only: 0 < R < 1.
    for bad in ["torus 1", "torus 0", "torus -0.5", "torus 1e-9"] {
        assert!(matches!(err(bad).kind, SceneErrorKind::ValueOutOfRange { what: "torus", .. }), "{bad}");
    }
    assert!(matches!(err("torus").kind, SceneErrorKind::WrongArgumentCount { .. }), "no radius");
}

#[test]
fn frusta_and_triangles_are_open_surfaces_outside_solids_only() {
    let scene = ok("frustum 0.5\nfrustum 1\nfrustum 0\ntriangle\n  scale 2 3 1");
    assert_eq!(scene.objects[0].primitive, Primitive::Frustum(crate::model::Taper::HALF));
    assert_eq!(scene.objects[1].primitive, Primitive::Frustum(crate::model::Taper::CYLINDER));
    assert_eq!(scene.objects[2].primitive, Primitive::Frustum(crate::model::Taper::from_steps(0)));
    assert_eq!(scene.objects[3].primitive, Primitive::Triangle);
    for bad in ["frustum 1.5", "frustum -0.1"] {
        assert!(matches!(err(bad).kind, SceneErrorKind::ValueOutOfRange { what: "frustum", .. }), "{bad}");
    }
    let error = err("union\n  sphere\n  triangle\nend");
    assert_eq!(error, SceneError { line: 3, kind: SceneErrorKind::OpenSurfaceInSolid { primitive: "triangle" } });
    assert!(error.to_string().starts_with("line 3: a triangle is an open surface, with no inside"), "{error}");
    assert_eq!(err("difference\n  cube\n  frustum 0.5\nend").kind, SceneErrorKind::OpenSurfaceInSolid { primitive: "frustum" });
    assert_eq!(err("union\n  cube\n  disc\nend").kind, SceneErrorKind::OpenSurfaceInSolid { primitive: "disc" });
}

#[test]
fn a_new_object_has_the_getobject_defaults() {
    let scene = ok("cube\ncylinder\ncone\nsphere");
    let primitives: Vec<_> = scene.objects.iter().map(|o| o.primitive).collect();
    assert_eq!(primitives, [Primitive::Cube, Primitive::Cylinder, Primitive::Cone, Primitive::Sphere]);
    for (index, object) in scene.objects.iter().enumerate() {
        assert_eq!(object.line, index as u32 + 1);
        assert_eq!(object.world_from_object, crate::geometry::Matrix4::IDENTITY);
        assert_eq!(
            object.material,
            Material { colour: 0, ka: 1.0, kd: 0.4, ks: 0.6, pwr: 20.0, rnd: 0.8, cmy: [0.3, 0.3, 0.3], reflect: 0.0, transmit: 0.0, ior: 1.0 }
        );
    }
}

#[test]
fn object_statements_change_only_the_most_recent_object() {
    let scene = ok("sphere\ncolour 3\nka 0.5\nkd 0.25\nks 0\npwr 1000000\nrnd 0\ncmy 0 0.5 1\ncube\ncolour 15\n");
    let sphere = scene.objects[0].material;
    assert_eq!(sphere, Material { colour: 3, ka: 0.5, kd: 0.25, ks: 0.0, pwr: 1.0e6, rnd: 0.0, cmy: [0.0, 0.5, 1.0], reflect: 0.0, transmit: 0.0, ior: 1.0 });
    assert_eq!(scene.objects[1].material, Material { colour: 15, ..Material::default() });
}

#[test]
fn later_global_statements_override_earlier_ones_and_may_follow_objects() {
    let scene = ok("viewport 0 9 0 9\nsphere\nviewport 1 2 3 4\nperspective 1 2 3\nparallel 0 1 0\n\
                    light point 1 1 1\nlight direction 0 0 2\nambient 0\nambient 0.5\nbackground 0\nbackground 255\n\
                    shadows on\nshadows off\ndither on\nviewplane -3\nviewplane 7.5e1\n");
    assert_eq!(scene.viewport, Viewport { x1: 1, x2: 2, y1: 3, y2: 4 });
    assert_eq!(scene.projection, Projection::Parallel { direction: [0.0, 1.0, 0.0] });
    // Lights add up (chapter 5): the first statement replaces the default, the next adds one.
    assert_eq!(scene.light, Light::Point([1.0, 1.0, 1.0]));
    assert_eq!(scene.more_lights.len(), 1);
    assert_eq!((scene.more_lights[0].light, scene.more_lights[0].intensity, scene.more_lights[0].line), (Light::Direction([0.0, 0.0, 2.0]), 1.0, 7));
    assert_eq!(scene.ambient, 0.5);
    assert_eq!(scene.background, 255);
    assert!(!scene.shadows);
    assert!(scene.dither);
    assert_eq!(scene.view_plane, 75.0);
    assert_eq!(scene.objects.len(), 1);
}

#[test]
fn viewport_limits_and_single_pixel() {
    let scene = ok("viewport 0 32767 5 5");
    assert_eq!(scene.viewport, Viewport { x1: 0, x2: 32767, y1: 5, y2: 5 });
    assert_eq!(scene.viewport.width(), 32768);
    assert_eq!(scene.viewport.height(), 1);
}

#[test]
fn group_up_and_down_use_the_palette() {
    let scene = ok("group 0 15 1 1 up\ngroup 15 3 9 15 down\ngroup 4 0 0 0 up\n");
    let mut expected = Palette::grey();
    expected.set_group_up(0, Rgb4::new(15, 1, 1));
    expected.set_group_down(15, Rgb4::new(3, 9, 15));
    expected.set_group_up(4, Rgb4::new(0, 0, 0));
    assert_eq!(scene.palette, expected);
    assert_eq!(scene.palette.entry(255), Rgb4::new(15, 15, 15));
    assert_eq!(scene.palette.entry(240 + 3), Rgb4::new(3, 9, 15));
}

#[test]
fn optimize_words() {
    let o = |text: &str| ok(text).optimizations;
    assert_eq!(o("optimize none"), Optimizations::NONE);
    assert_eq!(o("optimize all"), Optimizations::ALL);
    assert_eq!(o("optimize none\noptimize all"), Optimizations::ALL);
    assert_eq!(
        o("optimize grid"),
        Optimizations { pixelbuffer: false, extents: false, grid: true, sortlist: false }
    );
    assert_eq!(
        o("optimize sortlist\tpixelbuffer extents"),
        Optimizations { pixelbuffer: true, extents: true, grid: false, sortlist: true }
    );
    assert_eq!(o("optimize pixelbuffer extents grid sortlist grid"), Optimizations::ALL);
    check("optimize fast", 1, &["optimize", "`fast`", "pixelbuffer"]);
    check("\noptimize grid fast", 2, &["`fast`"]);
    check("optimize all grid", 1, &["`grid`", "on its own"]);
    check("optimize grid none", 1, &["`none`"]);
    check("optimize", 1, &["at least 1 argument", "found 0"]);
}

// ---------------------------------------------------------------- transforms

#[test]
fn transforms_compose_in_written_order() {
    // scale, then rotate z 90, then translate: (1,0,0) -> (2,0,0) -> (0,2,0) -> (0,2,5).
    let scene = ok("cube\nscale 2 1 1\nrotate z 90\ntranslate 0 0 5\n");
    let m = scene.objects[0].world_from_object;
    assert!(close(m.transform_point([1.0, 0.0, 0.0]), [0.0, 2.0, 5.0]));
    // The other order: translate first, then rotate, then scale.
    let scene = ok("cube\ntranslate 0 0 5\nrotate z 90\nscale 2 1 1\n");
    let m = scene.objects[0].world_from_object;
    assert!(close(m.transform_point([1.0, 0.0, 0.0]), [0.0, 1.0, 5.0]));
    // Rotations about x and y, right-handed, in degrees.
    let m = ok("sphere\nrotate x 90").objects[0].world_from_object;
    assert!(close(m.transform_point([0.0, 1.0, 0.0]), [0.0, 0.0, 1.0]));
    let m = ok("sphere\nrotate y -90").objects[0].world_from_object;
    assert!(close(m.transform_point([1.0, 0.0, 0.0]), [0.0, 0.0, 1.0]));
    // The parser builds exactly what the Matrix4 calls build.
    let mut expected = crate::geometry::Matrix4::IDENTITY;
    expected.scale([3.0, 0.5, -2.0]);
    expected.rotate(0, 30.0);
    expected.rotate(1, -70.0);
    expected.translate([10.0, -4.0, 7.0]);
    let scene = ok("cylinder\nscale 3 0.5 -2\nrotate x 30\nrotate y -70\ntranslate 10 -4 7");
    assert_eq!(scene.objects[0].world_from_object, expected);
}

#[test]
fn singular_transforms_are_rejected() {
    assert_eq!(check("sphere\nscale 1 0 1", 2, &["singular transform"]), SceneErrorKind::SingularTransform);
    check("sphere\nscale -0 1 1", 2, &["singular"]);
    check("sphere\nscale 1 1 0.0e5", 2, &["singular"]);
    // Each factor is fine, but together they underflow: reported at the object's first line
    // when the object ends (at the next object) ...
    check("sphere\nscale 1e-200 1e-200 1e-200\ncube\n", 1, &["singular"]);
    // ... or at the end of the input.
    check("cube\nsphere\n  scale 1e-200 1e-200 1e-200\n# end\n", 2, &["singular"]);
    // Overflow to infinity is not invertible either.
    check("\ncone\nscale 1e300 1 1\nscale 1e300 1 1\n", 2, &["singular"]);
    check("cone\ntranslate 1e308 0 0\ntranslate 1e308 0 0\n", 1, &["singular"]);
    // A later error in the same object comes first in reading order.
    check("sphere\nscale 1e-200 1e-200 1e-200\nfoo\n", 3, &["unknown keyword `foo`"]);
    // Tiny but invertible is fine.
    ok("sphere\nscale 1e-50 1e-50 1e-50");
}

// ---------------------------------------------------------------- numbers

#[test]
fn number_grammar() {
    let v = |token: &str| ok(&std::format!("viewplane {token}")).view_plane;
    assert_eq!(v("2"), 2.0);
    assert_eq!(v("-1.5"), -1.5);
    assert_eq!(v("+1.5"), 1.5);
    assert_eq!(v("1e-3"), 1e-3);
    assert_eq!(v("1E+3"), 1000.0);
    assert_eq!(v("007.50"), 7.5);
    assert_eq!(v("-0"), 0.0);
    assert_eq!(v("1e-400"), 0.0);
    assert_eq!(v("1.7976931348623157e308"), f64::MAX);
    for bad in [
        ".5", "5.", "-.5", "inf", "-inf", "nan", "NaN", "infinity", "0x10", "1,5", "1_000", "1e", "1e+", "e5", "+", "-",
        "--1", "+-1", "1..2", "1.2.3", "1e5.5", "1 e5", "½", "１", "1f", "0b1", "1.5e3x",
    ] {
        let text = std::format!("viewplane {bad}");
        let error = err(&text);
        match error.kind {
            SceneErrorKind::MalformedNumber { what, .. } => assert_eq!(what, "viewplane D"),
            // "1 e5" has two arguments.
            SceneErrorKind::WrongArgumentCount { found: 2, .. } => assert_eq!(bad, "1 e5"),
            other => panic!("{bad:?}: {other:?}"),
        }
        assert_eq!(error.line, 1);
    }
    for huge in ["1e400", "-1e400", "1e99999999999999999999999", "179769313486231580000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000"] {
        let kind = check(&std::format!("\n\nviewplane {huge}"), 3, &["out of range", "viewplane D"]);
        assert!(matches!(kind, SceneErrorKind::NumberNotFinite { .. }), "{huge}: {kind:?}");
    }
}

#[test]
fn integers_must_be_whole() {
    assert_eq!(ok("background 1e2").background, 100);
    assert_eq!(ok("background 1.0").background, 1);
    assert_eq!(ok("background 2.50e1").background, 25);
    assert_eq!(ok("background -0").background, 0);
    assert_eq!(ok("background +7").background, 7);
    assert_eq!(ok("background 0.0000e0").background, 0);
    assert_eq!(ok("background 12500e-2").background, 125);
    assert_eq!(ok("sphere\ncolour 15.000").objects[0].material.colour, 15);
    for (text, what) in [
        ("background 1.5", "background"),
        ("background 1.0000000000000000001", "background"),
        ("background 1e-400", "background"),
        ("background 125e-2", "background"),
        ("viewport 0 1.5 0 1", "viewport X2"),
        ("group 1.5 1 1 1 up", "group N"),
        ("group 1 1 1 0.1 up", "group B"),
        ("sphere\ncolour 0.5", "colour"),
    ] {
        let line = text.lines().count() as u32;
        let kind = check(text, line, &["expected an integer", what]);
        assert!(matches!(kind, SceneErrorKind::ExpectedInteger { .. }), "{text}: {kind:?}");
    }
}

#[test]
fn integer_ranges() {
    for (text, parts) in [
        ("viewport 0 32768 0 1", &["viewport X2", "`32768`", "0 to 32767"][..]),
        ("viewport -1 10 0 1", &["viewport X1", "`-1`"]),
        ("viewport 0 10 0 1e10", &["viewport Y2"]),
        ("background 256", &["background", "0 to 255"]),
        ("background -1", &["background"]),
        ("group 16 1 1 1 up", &["group N", "0 to 15"]),
        ("group 1 16 1 1 up", &["group R"]),
        ("group 1 1 16 1 down", &["group G"]),
        ("group 1 1 1 -1 down", &["group B"]),
        ("cube\ncolour 16", &["colour", "`16`", "0 to 15"]),
    ] {
        let line = text.lines().count() as u32;
        let kind = check(text, line, parts);
        assert!(matches!(kind, SceneErrorKind::IntegerOutOfRange { .. }), "{text}: {kind:?}");
    }
}

#[test]
fn real_ranges() {
    for (text, parts) in [
        ("ambient -0.1", &["ambient", "at least 0"][..]),
        ("cube\nka -1", &["ka", "`-1`"]),
        ("cube\nkd -1e-9", &["kd"]),
        ("cube\nks -2", &["ks"]),
        ("cube\nrnd -0.5", &["rnd"]),
        ("cube\npwr -1", &["pwr", "0 to 1000000"]),
        ("cube\npwr 1000001", &["pwr"]),
        ("cube\ncmy -0.1 0 0", &["cmy C", "0 to 1"]),
        ("cube\ncmy 0 1.5 0", &["cmy M"]),
        ("cube\ncmy 0 0 2", &["cmy Y"]),
    ] {
        let line = text.lines().count() as u32;
        let kind = check(text, line, parts);
        assert!(matches!(kind, SceneErrorKind::ValueOutOfRange { .. }), "{text}: {kind:?}");
    }
}

// ---------------------------------------------------------------- every error kind

#[test]
fn unknown_keywords() {
    for (text, line, token) in [
        ("foo", 1, "`foo`"),
        ("\n\n  Sphere", 3, "`Sphere`"),
        ("sphere\ncolor 1", 2, "`color`"),
        ("viewport0 1 2 3", 1, "`viewport0`"),
        ("sphere\r\r\n", 1, "`sphere\\r`"),
        ("  \t x # comment", 1, "`x`"),
    ] {
        let kind = check(text, line, &["unknown keyword", token]);
        assert!(matches!(kind, SceneErrorKind::UnknownKeyword { .. }));
    }
}

#[test]
fn wrong_argument_counts() {
    for (text, line, parts) in [
        ("viewport 0 1 2", 1, &["`viewport` takes 4 arguments", "found 3", "viewport X1 X2 Y1 Y2"][..]),
        ("window 1 2 3 4 5", 1, &["`window` takes 4 arguments", "found 5"]),
        ("viewplane", 1, &["`viewplane` takes 1 argument ", "found 0"]),
        ("perspective 1 2", 1, &["takes 3 arguments"]),
        ("parallel 1 2 3 4", 1, &["takes 3 arguments"]),
        ("light point 1 2", 1, &["`light` takes 4 or 5 arguments", "found 3"]),
        ("light point 1 2 3 4 5", 1, &["`light` takes 4 or 5 arguments", "found 6"]),
        ("antialias 0.1 2 3", 1, &["`antialias` takes 1 or 2 arguments", "found 3"]),
        ("depth", 1, &["`depth` takes 1 argument", "found 0"]),
        ("sphere\nreflect", 2, &["`reflect` takes 1 argument", "found 0"]),
        ("light 1 2 3", 1, &["found 3"]),
        ("ambient 1 2", 1, &["takes 1 argument"]),
        ("background", 1, &["takes 1 argument"]),
        ("shadows", 1, &["`shadows` takes 1 argument"]),
        ("dither on off", 1, &["found 2"]),
        ("group 1 2 3 4", 1, &["`group` takes 5 arguments"]),
        ("sphere 1", 1, &["`sphere` takes no arguments", "found 1"]),
        ("cube x", 1, &["`cube` takes no arguments"]),
        ("sphere\nscale 2", 2, &["`scale` takes 3 arguments", "found 1"]),
        ("sphere\nrotate 30", 2, &["`rotate` takes 2 arguments"]),
        ("sphere\ntranslate", 2, &["takes 3 arguments", "found 0"]),
        ("sphere\ncolour", 2, &["takes 1 argument"]),
        ("sphere\nka 1 2", 2, &["`ka` takes 1 argument"]),
        ("sphere\ncmy 0.1 0.2", 2, &["`cmy` takes 3 arguments"]),
    ] {
        let kind = check(text, line, parts);
        assert!(matches!(kind, SceneErrorKind::WrongArgumentCount { .. }), "{text}: {kind:?}");
    }
}

#[test]
fn invalid_words() {
    for (text, line, parts) in [
        ("shadows maybe", 1, &["`shadows`", "`maybe`", "`on` or `off`"][..]),
        ("shadows ON", 1, &["`ON`"]),
        ("dither 1", 1, &["`dither`", "`1`"]),
        ("light spot 1 2 3", 1, &["`light`", "`spot`", "`point` or `direction`"]),
        ("sphere\nrotate w 10", 2, &["`rotate`", "`w`", "`x`, `y` or `z`"]),
        ("sphere\nrotate X 10", 2, &["`X`"]),
        ("group 1 2 3 4 sideways", 1, &["`group`", "`sideways`", "`up` or `down`"]),
        ("optimize fast", 1, &["`optimize`", "`fast`"]),
    ] {
        let kind = check(text, line, parts);
        assert!(matches!(kind, SceneErrorKind::InvalidWord { .. }), "{text}: {kind:?}");
    }
}

#[test]
fn invalid_rectangles() {
    for (text, parts) in [
        ("viewport 10 9 0 0", &["viewport", "X1 must not be greater than X2"][..]),
        ("viewport 0 0 2 1", &["viewport", "Y1 must not be greater than Y2"]),
        ("window 1 1 0 1", &["window", "X1 must be less than X2"]),
        ("window 2 1 0 1", &["X1 must be less than X2"]),
        ("window 0 1 5 -5", &["Y1 must be less than Y2"]),
        ("window -1e308 1e308 0 1", &["too large"]),
    ] {
        let kind = check(text, 1, parts);
        assert!(matches!(kind, SceneErrorKind::InvalidRectangle { .. }), "{text}: {kind:?}");
    }
}

#[test]
fn zero_directions() {
    for text in ["parallel 0 0 0", "parallel -0 0.0 0e5", "light direction 0 0 0", "parallel 1e-200 0 0", "light direction 1e200 0 0"] {
        assert_eq!(check(&std::format!("# c\n{text}"), 2, &["zero vector"]), SceneErrorKind::ZeroDirection);
    }
    // A point light at the origin is fine, and so is a perspective eye there.
    assert_eq!(ok("light point 0 0 0").light, Light::Point([0.0; 3]));
    assert_eq!(ok("perspective 0 0 0").projection, Projection::Perspective { eye: [0.0; 3] });
}

#[test]
fn statements_before_the_first_object() {
    for keyword in ["scale 1 1 1", "rotate x 1", "translate 1 1 1", "colour 1", "ka 1", "kd 1", "ks 1", "pwr 1", "rnd 1", "cmy 1 1 1", "scale"] {
        let name = keyword.split(' ').next().unwrap();
        let kind = check(&std::format!("viewport 0 1 0 1\n\n{keyword}\nsphere"), 3, &[&std::format!("`{name}`"), "no object"]);
        assert!(matches!(kind, SceneErrorKind::ObjectRequired { .. }));
    }
}

#[test]
fn too_many_objects() {
    let text = "sphere\ncube\n# third:\ncone\n";
    let error = parse::<2>(text.as_bytes()).unwrap_err();
    assert_eq!(error, SceneError { line: 4, kind: SceneErrorKind::TooManyObjects { capacity: 2 } });
    assert_eq!(error.to_string(), "line 4: too many objects: this build holds at most 2");
    assert_eq!(parse::<3>(text.as_bytes()).unwrap().objects.len(), 3);
    let error = parse::<0>(b"\ncylinder").unwrap_err();
    assert_eq!(error, SceneError { line: 2, kind: SceneErrorKind::TooManyObjects { capacity: 0 } });
    // Globals alone fit a zero-capacity build.
    assert!(parse::<0>(b"viewport 0 1 0 1").is_ok());
}

#[test]
fn invalid_utf8() {
    let error = err_bytes(b"sphere\nscale 1 \xff 1\n");
    assert_eq!(error, SceneError { line: 2, kind: SceneErrorKind::InvalidUtf8 });
    assert!(error.to_string().contains("UTF-8"));
    assert_eq!(err_bytes(b"\xc3\n").line, 1);
    assert_eq!(err_bytes(b"\n\n\xed\xa0\x80").line, 3); // a surrogate
    // Anything goes in a comment.
    assert_eq!(parse::<4>(b"sphere # \xff\xfe caf\xc3\n# \x00\x80\nkd 0.5 #\xff").unwrap().objects[0].material.kd, 0.5);
    // Valid UTF-8 that is not a keyword is an unknown keyword, not a UTF-8 error.
    assert!(matches!(err("sphère").kind, SceneErrorKind::UnknownKeyword { .. }));
}

#[test]
fn line_endings_and_blank_space() {
    let scene = ok("\r\nsphere\r\n\tkd\t0.5\r\n  # comment\r\n\r\ncube   \r\ncolour 2\r");
    assert_eq!(scene.objects.len(), 2);
    assert_eq!((scene.objects[0].line, scene.objects[1].line), (2, 6));
    assert_eq!(scene.objects[0].material.kd, 0.5);
    assert_eq!(scene.objects[1].material.colour, 2);
    // Line numbers count blank, comment and CRLF lines.
    assert_eq!(err("\r\n#\r\n\r\nbogus\r\n").line, 4);
    // A comment directly after a token ends it.
    assert_eq!(ok("sphere#x\nkd 0.25#y").objects[0].material.kd, 0.25);
}

#[test]
fn long_tokens_are_truncated_in_messages() {
    let long = "x".repeat(1000);
    let error = err(&long);
    let message = error.to_string();
    assert_eq!(message, std::format!("line 1: unknown keyword `{}...`", "x".repeat(TOKEN_EXCERPT_BYTES)));
    let multibyte = "é".repeat(50);
    let message = err(&std::format!("viewplane {multibyte}")).to_string();
    assert!(message.contains(&std::format!("`{}...`", "é".repeat(10))), "{message}");
    // Control characters are escaped.
    let message = err("\u{1b}[2J").to_string();
    assert!(message.contains("`\\u{1b}[2J`"), "{message}");
    let token = Token::new("short");
    assert_eq!((token.as_str(), token.is_truncated()), ("short", false));
}

#[test]
fn preparation_kinds_display() {
    let e = SceneError { line: 7, kind: SceneErrorKind::PrimitiveNotCompiled { primitive: "cone" } };
    assert_eq!(e.to_string(), "line 7: cone is not compiled into this build");
    let kind = SceneErrorKind::OutOfRangeForNumberType { what: "the object's bounding volume", number: "fixed", value: 30000.5, limit: 26000.0 };
    let e = SceneError { line: 12, kind };
    assert_eq!(
        e.to_string(),
        "line 12: the object's bounding volume reaches 30000.5, too large for the number type `fixed`, whose \
         documented range for scene values is ±26000 (see docs/hard-cases.md)"
    );
    let kind = SceneErrorKind::OutOfRangeForNumberType { what: "the light", number: "f32", value: 2e20, limit: 1e18 };
    assert!(SceneError { line: 0, kind }.to_string().contains("reaches 2e20, too large for the number type `f32`"));
}

#[test]
fn every_message_is_nonempty_and_names_its_line() {
    let texts = [
        "foo", "viewport 1", "shadows x", "viewplane .5", "viewplane 1e999", "background 0.5", "background 300", "ambient -1",
        "window 1 0 0 1", "parallel 0 0 0", "scale 1 1 1", "sphere\nscale 0 1 1",
    ];
    for text in texts {
        let error = err(text);
        let message = error.to_string();
        let prefix = std::format!("line {}: ", error.line);
        assert!(message.starts_with(&prefix) && message.len() > prefix.len() + 5, "{message}");
        assert!(error.line >= 1);
    }
}

#[test]
fn a_long_line_is_handled() {
    // A 1 MB number, a 1 MB run of tokens, and a 1 MB comment (the 10 MB cases are in the
    // integration test, in release-like builds).
    let digits = "9".repeat(1 << 20);
    assert!(matches!(err(&std::format!("viewplane {digits}")).kind, SceneErrorKind::NumberNotFinite { .. }));
    let small = std::format!("viewplane 0.{digits}");
    assert_eq!(ok(&small).view_plane, 1.0);
    let many = "1 ".repeat(1 << 19);
    match err(&std::format!("viewport {many}")).kind {
        SceneErrorKind::WrongArgumentCount { found, .. } => assert_eq!(found, 1 << 19),
        other => panic!("{other:?}"),
    }
    let comment = std::format!("sphere #{}", "\u{ff}".repeat(1 << 19));
    assert_eq!(ok(&comment).objects.len(), 1);
}

#[test]
fn exact_messages() {
    for (text, message) in [
        ("viewport 0 1 2", "line 1: `viewport` takes 4 arguments (`viewport X1 X2 Y1 Y2`), found 3"),
        ("\nsphere 2", "line 2: `sphere` takes no arguments (`sphere`), found 1"),
        ("optimize", "line 1: `optimize` takes at least 1 argument (`optimize all|none|pixelbuffer extents grid sortlist`), found 0"),
        ("bogus 1 2", "line 1: unknown keyword `bogus`"),
        ("spheer", "line 1: unknown keyword `spheer` (did you mean `sphere`?)"),
        ("Sphere", "line 1: unknown keyword `Sphere` (did you mean `sphere`?)"),
        ("trnaslate 1 2 3", "line 1: unknown keyword `trnaslate` (did you mean `translate`?)"),
        ("colur 3", "line 1: unknown keyword `colur` (did you mean `colour`?)"),
        ("shadows maybe", "line 1: `shadows`: invalid word `maybe`, expected `on` or `off`"),
        ("background 1.5", "line 1: background: expected an integer, found `1.5`"),
        ("background 300", "line 1: background: `300` is out of range (must be an integer from 0 to 255)"),
        ("ambient -1", "line 1: ambient: `-1` is out of range (must be at least 0)"),
        ("viewplane 1e400", "line 1: viewplane D: number `1e400` is out of range (too large for a 64-bit float)"),
        ("window 1 0 0 1", "line 1: window: X1 must be less than X2"),
        ("sphere\nscale 0 1 1", "line 2: singular transform: the object's transform cannot be inverted"),
        ("ka 1", "line 1: `ka` changes the most recent object, but no object has started yet (start one with cube, sphere, cylinder, cone, torus, frustum, triangle or disc, or a solid: union, intersection or difference)"),
        ("parallel 0 0 0", "line 1: the direction is the zero vector (or too small or too large for its length to be computed)"),
    ] {
        assert_eq!(err(text).to_string(), message);
    }
    assert!(err("viewplane .5").to_string().starts_with("line 1: viewplane D: malformed number `.5` (expected"));
    assert_eq!(err_bytes(b"\xff").to_string(), "line 1: the statement is not valid UTF-8 text");
}

#[test]
fn chapter_five_statements_parse_with_their_defaults_and_ranges() {
    let scene = ok("sphere\n reflect 0.7\n transmit 0.25\n ior 1.5\ncube\ndepth 3\nantialias 0.1 4\nlight point 1 2 3 0.5\nlight direction 0 1 0\nlight point 4 5 6 2\n");
    let glass = scene.objects[0].material;
    assert_eq!((glass.reflect, glass.transmit, glass.ior), (0.7, 0.25, 1.5));
    let plain = scene.objects[1].material;
    assert_eq!((plain.reflect, plain.transmit, plain.ior), (0.0, 0.0, 1.0));
    assert_eq!(scene.depth, 3);
    assert_eq!(scene.antialias, Some(Antialias { threshold: 0.1, levels: 4 }));
    assert_eq!((scene.light, scene.light_intensity), (Light::Point([1.0, 2.0, 3.0]), 0.5));
    assert_eq!(scene.more_lights.iter().map(|l| (l.light, l.intensity)).collect::<Vec<_>>(), [(Light::Direction([0.0, 1.0, 0.0]), 1.0), (Light::Point([4.0, 5.0, 6.0]), 2.0)]);
    assert!(scene.uses_chapter_five());
    let defaults = ok("sphere\n");
    assert_eq!((defaults.depth, defaults.antialias, defaults.light_intensity, defaults.more_lights.len()), (5, None, 1.0, 0));
    assert!(!defaults.uses_chapter_five());
    assert_eq!(ok("antialias 0.2\nantialias off\n").antialias, None);
    assert_eq!(ok("antialias 0.2\n").antialias, Some(Antialias { threshold: 0.2, levels: 2 }));

    check("sphere\nreflect 1.5", 2, &["reflect: `1.5` is out of range (must be from 0 to 1)"]);
    check("sphere\ntransmit -0.1", 2, &["transmit: `-0.1` is out of range (must be from 0 to 1)"]);
    check("sphere\nior 0", 2, &["ior: `0` is out of range (must be from 0.1 to 10)"]);
    check("reflect 0.5", 1, &["`reflect` changes the most recent object"]);
    check("depth 0", 1, &["depth: `0` is out of range (must be an integer from 1 to 8)"]);
    check("depth 2.5", 1, &["depth: expected an integer"]);
    check("antialias 2", 1, &["antialias T: `2` is out of range (must be from 0 to 1)"]);
    check("antialias 0.1 5", 1, &["antialias L: `5` is out of range (must be an integer from 1 to 4)"]);
    check("antialias on", 1, &["antialias T: malformed number `on`"]);
    check("light point 0 0 0 -1", 1, &["light I: `-1` is out of range (must be at least 0)"]);
    check(&"light point 0 0 0\n".repeat(9), 9, &["too many lights: a scene holds at most 8"]);
}

/// The nodes of the scene's solids as a compact string: `P` a primitive (its keyword's first
/// letter), `U`, `I`, `D` an operation.
fn solid_shape(scene: &SceneDescription<64>) -> std::string::String {
    scene
        .solids
        .iter()
        .map(|node| match node {
            SolidNode::Leaf(leaf) => leaf.primitive.name().chars().next().unwrap().to_ascii_lowercase(),
            SolidNode::Combine { operation: Operation::Union, .. } => 'U',
            SolidNode::Combine { operation: Operation::Intersection, .. } => 'I',
            SolidNode::Combine { operation: Operation::Difference, .. } => 'D',
        })
        .collect()
}

#[test]
fn solids_parse_into_post_order_chains_and_nest() {
    // `difference A B C` is (A − B) − C; a nested solid is one operand.
    let scene = ok("difference\n cube\n sphere\n cylinder\nend\nsphere\nunion\n cone\n intersection\n  sphere\n  cube\n end\nend\n");
    assert_eq!(solid_shape(&scene), "csDcDcscIU");
    assert_eq!(scene.objects.len(), 3);
    assert_eq!(scene.objects[0].primitive, Primitive::Solid(SolidRange { first: 0, count: 5 }));
    assert_eq!(scene.objects[1].primitive, Primitive::Sphere);
    assert_eq!(scene.objects[2].primitive, Primitive::Solid(SolidRange { first: 5, count: 5 }));
    // One operand: the solid is that operand.
    assert_eq!(solid_shape(&ok("union\n torus 0.5\nend\n")), "t");
}

#[test]
fn statements_after_end_compose_on_every_operand_and_materials_are_inherited() {
    let scene = ok("union\n sphere\n  translate 1 0 0\n  colour 3\n sphere\n  kd 0.9\n difference\n  cube\n  cube\n   colour 5\n end\n  colour 7\nend\n scale 2 2 2\n colour 9\n ks 0.1\n");
    let leaves: std::vec::Vec<&ObjectDescription> = scene.solids.iter().filter_map(|node| if let SolidNode::Leaf(leaf) = node { Some(leaf) } else { None }).collect();
    // The first sphere was moved, then the whole solid scaled: its centre is at x = 2.
    assert_eq!(leaves[0].world_from_object.transform_point([0.0; 3]), [2.0, 0.0, 0.0]);
    assert_eq!(leaves[1].world_from_object.transform_point([1.0, 1.0, 1.0]), [2.0, 2.0, 2.0]);
    // Its own colour kept; the second sphere set kd, so it keeps its own (default colour);
    // the inner difference's first cube takes the difference's colour 7, the second its own 5.
    assert_eq!((leaves[0].material.colour, leaves[0].material.ks), (3, Material::default().ks));
    assert_eq!((leaves[1].material.colour, leaves[1].material.kd), (0, 0.9));
    assert_eq!((leaves[2].material.colour, leaves[3].material.colour), (7, 5));
    // The solid's own material: what nothing below overrides.
    assert_eq!((scene.objects[0].material.colour, scene.objects[0].material.ks), (9, 0.1));
    // The object is the enclosing box: the spheres' union with the difference's left cube.
    let corner = scene.objects[0].world_from_object.transform_point([0.0; 3]);
    let far = scene.objects[0].world_from_object.transform_point([1.0; 3]);
    assert_eq!((corner, far), ([-2.0, -2.0, -2.0], [4.0, 2.0, 2.0]));
}

#[test]
fn an_intersection_is_enclosed_by_the_overlap_and_a_difference_by_its_left_operand() {
    let scene = ok("intersection\n cube\n  scale 4 4 4\n sphere\n  translate 4 4 4\nend\ndifference\n cube\n sphere\n  scale 5 5 5\nend\n");
    let boxes: std::vec::Vec<([f64; 3], [f64; 3])> =
        scene.objects.iter().map(|object| (object.world_from_object.transform_point([0.0; 3]), object.world_from_object.transform_point([1.0; 3]))).collect();
    assert_eq!(boxes, [([3.0; 3], [4.0; 3]), ([0.0; 3], [1.0; 3])]);
}

#[test]
fn solid_errors_name_their_lines() {
    assert_eq!(err("cube\nunion\n sphere\n").to_string(), "line 2: the `union` opened here is never closed with `end`");
    assert_eq!(err("end").to_string(), "line 1: `end` with no solid open (open one with union, intersection or difference)");
    assert_eq!(err("union\n intersection\n end\nend").to_string(), "line 3: `end` closes the `intersection` of line 2, which has no operand (a solid needs at least one object)");
    assert!(matches!(err("union\n sphere\n union\n  cube\n  ior 1.5\n end\nend").kind, SceneErrorKind::OpticsOnOperand { keyword: "ior" }));
    assert!(matches!(err("difference\ncolour 2\n").kind, SceneErrorKind::OperandRequired { keyword: "colour" }));
    // A singular operand is named by its own line, found when the solid is complete.
    assert_eq!(err("union\n sphere\n cube\n  scale 1e-300 1 1\n  scale 1e-300 1 1\nend").line, 3);
    // Reflection on the whole solid is allowed.
    assert_eq!(ok("union\n sphere\nend\n reflect 0.5\n").objects[0].material.reflect, 0.5);
}
