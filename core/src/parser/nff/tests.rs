extern crate std;
use std::format;
use std::vec::Vec;

use super::*;
use crate::model::{Primitive, SceneErrorKind};

type Scene = Description<heapless::Vec<ObjectDescription, 64>>;

fn ok(text: &str) -> Scene {
    parse_into_list(text.as_bytes()).unwrap_or_else(|error| panic!("{error}\n{text}"))
}

fn err(text: &str) -> SceneError {
    parse_into_list::<heapless::Vec<ObjectDescription, 64>>(text.as_bytes()).err().unwrap_or_else(|| panic!("accepted:\n{text}"))
}

const VIEW: &str = "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 90\nhither 1\nresolution 64 48\n";

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
}

#[test]
fn the_view_becomes_the_camera_frame() {
    let scene = ok(&format!("{VIEW}s 0 0 0 2\n"));
    assert_eq!(scene.viewport, Viewport { x1: 0, x2: 63, y1: 0, y2: 47 });
    // 90 degrees: the window's half height is tan 45° = 1 at the view plane z = -1.
    assert!((scene.window.y2 - 1.0).abs() < 1e-12 && (scene.window.y1 + 1.0).abs() < 1e-12);
    assert!((scene.window.x2 - 63.0 / 47.0).abs() < 1e-12, "square pixels");
    assert_eq!(scene.view_plane, -1.0);
    assert_eq!(scene.projection, Projection::Perspective { eye: [0.0; 3] });
    // The sphere at the origin is 10 in front of the eye: at z = -10, radius 2.
    let m = scene.objects[0].world_from_object;
    assert!(close(m.transform_point([0.0; 3]), [0.0, 0.0, -10.0]), "{m:?}");
    assert!(close(m.transform_point([1.0, 0.0, 0.0]), [2.0, 0.0, -10.0]), "{m:?}");
    // A view from the side: x of the world is seen along -z.
    let scene = ok("v from 5 0 0 at 0 0 0 up 0 0 1 angle 40 hither 0.1 resolution 8 8\ns 1 0 0 1\n");
    assert!(close(scene.objects[0].world_from_object.transform_point([0.0; 3]), [0.0, 0.0, -4.0]));
}

#[test]
fn lights_materials_and_background() {
    let scene = ok(&format!("b 0.1 0.2 0.8\n{VIEW}l 0 10 10\nl 1 2 3 0.5 0.5 0.5\nl 4 5 6\nf 1 0 0 0.7 0.3 40 0 0\ns 0 0 0 1\nf 0 0 1 0.5 0 0 0.6 1.5\ns 1 1 1 1\n"));
    // Three lights, each 1/√3 (the second weighted by its grey colour).
    let share = 1.0 / 3f64.sqrt();
    assert!((scene.light_intensity - share).abs() < 1e-12);
    assert_eq!(scene.more_lights.len(), 2);
    assert!((scene.more_lights[0].intensity - share * 0.5).abs() < 1e-12);
    assert_eq!(scene.light, Light::Point([0.0, 10.0, 0.0]));
    let (red, blue) = (scene.objects[0].material, scene.objects[1].material);
    assert_eq!((red.kd, red.ks, red.pwr, red.reflect, red.transmit, red.ior), (0.7, 0.3, 40.0, 0.3, 0.0, 1.0));
    assert_eq!((blue.transmit, blue.ior), (0.6, 1.5));
    assert_ne!(red.colour, blue.colour);
    assert_eq!(scene.palette.entry(16 * red.colour + 15), Rgb4::new(15, 0, 0));
    // The background's group is its colour's ramp, at the shade of its brightest channel.
    let background = scene.palette.entry(scene.background);
    assert_eq!(background, Rgb4::new(2, 3, 12), "{:?}", scene.background);
    assert!(scene.shadows);
}

#[test]
fn cones_become_frusta_narrow_end_first() {
    let scene = ok(&format!("{VIEW}c 0 0 0 2 0 4 0 1\nc\n0 0 0 1\n0 1 0 1\n"));
    let Primitive::Frustum(taper) = scene.objects[0].primitive else { panic!("{:?}", scene.objects[0].primitive) };
    assert_eq!(taper.to_f64(), 0.5);
    let m = scene.objects[0].world_from_object;
    // z = 0 at the narrow end (the apex at y = 4), z = 1 at the base; radius 2 there.
    assert!(close(m.transform_point([0.0; 3]), [0.0, 4.0, -10.0]), "{m:?}");
    assert!(close(m.transform_point([0.0, 0.0, 1.0]), [0.0, 0.0, -10.0]), "{m:?}");
    let rim = m.transform_point([1.0, 0.0, 1.0]);
    assert!(((rim[0]).powi(2) + (rim[2] + 10.0).powi(2) - 4.0).abs() < 1e-12, "{rim:?}");
    assert_eq!(scene.objects[1].primitive, Primitive::Frustum(Taper::CYLINDER));
}

#[test]
fn polygons_and_patches_become_triangles() {
    let scene = ok(&format!("{VIEW}p 4\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\npp 3\n0 0 1 0 0 1\n1 0 1 0 0 1\n0 1 1 0 0 1\n"));
    assert_eq!(scene.objects.len(), 3);
    assert!(scene.objects[..2].iter().all(|o| o.primitive == Primitive::Triangle));
    // The patch keeps its normals: all along +z in the world (toward the eye), so in object
    // space each carried back is the plane's normal, the third axis.
    let Primitive::Patch(normals) = scene.objects[2].primitive else { panic!("{:?}", scene.objects[2].primitive) };
    assert_eq!(normals.0, [[0, 0, 32767]; 3]);
    // The patch's corners are where its vertices are.
    let m = scene.objects[2].world_from_object;
    let corners: Vec<[f64; 3]> = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]].iter().map(|p| m.transform_point(*p)).collect();
    for want in [[0.0, 0.0, -9.0], [1.0, 0.0, -9.0], [0.0, 1.0, -9.0]] {
        assert!(corners.iter().any(|c| close(*c, want)), "{corners:?}");
    }
    // A polygon of no area adds nothing.
    assert_eq!(ok(&format!("{VIEW}p 3\n0 0 0\n1 1 1\n2 2 2\n")).objects.len(), 0);
}

#[test]
fn comments_and_numbers_across_lines() {
    let scene = ok(&format!("# a comment\n{VIEW}s 0 0 0 # the centre\n 1.5e0\n"));
    assert_eq!(scene.objects.len(), 1);
}

#[test]
fn errors_name_the_line_and_the_problem() {
    assert_eq!(err(&format!("{VIEW}q 1 2 3")), SceneError::new(8, SceneErrorKind::UnknownKeyword { keyword: Token::new("q"), suggestion: None }));
    assert_eq!(err(&format!("{VIEW}s 0 0 zero 1")).kind, SceneErrorKind::MalformedNumber { what: "s centre", token: Token::new("zero") });
    assert_eq!(err(&format!("{VIEW}s 0 0 0")), SceneError::new(8, SceneErrorKind::UnexpectedEnd { expected: "s radius" }));
    assert_eq!(err(&format!("{VIEW}p 4\n0 0 0\n1 0 0\n1 1 0\n")).kind, SceneErrorKind::UnexpectedEnd { expected: "p vertex" });
    assert!(matches!(err(&format!("{VIEW}p 2\n0 0 0\n1 0 0\n")).kind, SceneErrorKind::IntegerOutOfRange { what: "p vertex count", .. }));
    assert_eq!(err("s 0 0 0 1\n").line, 1, "an object before the view");
    assert!(matches!(err("v\nfrom 0 0 1\nat 0 0 0\nup 0 0 1\nangle 45\n").kind, SceneErrorKind::ZeroDirection), "up along the view");
    assert_eq!(err("v\nfrom 0 0 1\nat 0 0 0\nangle 45\n").kind, SceneErrorKind::UnexpectedEnd { expected: "`up` of the view" });
    assert!(matches!(err(&format!("{VIEW}f 1 1 1 0.5 0.5 10 1.5 1.2\n")).kind, SceneErrorKind::ValueOutOfRange { what: "f T", .. }));
    assert!(matches!(err(&format!("{VIEW}c 0 0 0 1 0 0 0 1\n")).kind, SceneErrorKind::InvalidRectangle { what: "c", .. }));
    assert_eq!(err(&format!("{VIEW}s 0 0 0 1e999\n")).kind, SceneErrorKind::NumberNotFinite { what: "s radius", token: Token::new("1e999") });
    let text = format!("{VIEW}{}", "l 0 0 0\n".repeat(MAX_LIGHTS + 1));
    assert_eq!(err(&text), SceneError::new(8 + MAX_LIGHTS as u32, SceneErrorKind::TooManyLights { capacity: MAX_LIGHTS }));
}

/// Every small SPD scene of the repository reads.
#[test]
fn the_small_spd_scenes_read() {
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/spd");
    let mut read = 0;
    for entry in std::fs::read_dir(&folder).unwrap().flatten() {
        let path = entry.path();
        if path.extension().is_some_and(|e| e == "nff") {
            let text = std::fs::read(&path).unwrap();
            let scene = parse_into_list::<heapless::Vec<ObjectDescription, 1024>>(&text);
            assert!(scene.is_ok(), "{}: {:?}", path.display(), scene.err());
            read += 1;
        }
    }
    assert_eq!(read, 7);
}

/// A patch's shading normal, carried out of object space as any object's, is the world
/// normals interpolated at the hit (here 1/2, 1/4, 1/4 of the three).
#[test]
fn a_patch_interpolates_its_world_normals() {
    use crate::geometry::{AffineTransform, Ray, Vector3};
    use crate::shapes::Interval;
    let s = core::f64::consts::FRAC_1_SQRT_2;
    let scene = ok(&format!("{VIEW}pp 3\n0 0 0 0 0 1\n1 0 0 {s} 0 {s}\n0 1 0 0 {s} {s}\n"));
    let object = scene.objects[0];
    let Primitive::Patch(_) = object.primitive else { panic!("{:?}", object.primitive) };
    let object_from_world = AffineTransform::<f64>::from_matrix(&object.world_from_object.affine_inverse().unwrap());
    let world = Ray { origin: Vector3::from_f64([0.0; 3]), direction: Vector3::from_f64([0.25, 0.25, -10.0]) };
    let hit = object.primitive.intersect(&object_from_world.ray(&world), Interval::unbounded()).unwrap();
    assert!((hit.t - 1.0).abs() < 1e-12, "{}", hit.t);
    let normal = object_from_world.transposed_vector(hit.normal).to_f64();
    let want = [0.25 * s, 0.25 * s, 0.5 + 0.5 * s];
    let length = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let (a, b) = (length(normal), length(want));
    for k in 0..3 {
        assert!((normal[k] / a - want[k] / b).abs() < 1e-4, "{normal:?} against {want:?}");
    }
}
