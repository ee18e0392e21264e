//! The range check at preparation: each kind of value that can be too large is caught, in the
//! types that cannot hold it, with the object's line; scenes inside the range prepare.

extern crate std;

use crate::number::{Fixed, Fixed16, Number};
use crate::model::{SceneError, SceneErrorKind};
use crate::parser::parse;
use crate::scene::Scene;

const CAPACITY: usize = 4;

fn prepare<N: Number>(text: &str) -> Result<(), SceneError> {
    let description = parse::<CAPACITY>(text.as_bytes()).unwrap();
    Scene::<N, CAPACITY>::prepare(&description).map(|_| ())
}

/// The error's line and what it names, or a panic naming the text when the scene prepared.
fn rejection<N: Number>(text: &str) -> (u32, &'static str, f64) {
    match prepare::<N>(text) {
        Err(SceneError { line, kind: SceneErrorKind::OutOfRangeForNumberType { what, number, value, limit } }) => {
            assert_eq!((number, limit), (N::NAME, N::SCENE_LIMIT));
            assert!(value > limit, "{value} {limit}");
            (line, what, value)
        }
        other => panic!("{}: expected a range error for {text:?}, got {other:?}", N::NAME),
    }
}

const CAMERA: &str = "viewport 0 15 0 15\nwindow -2 2 -2 2\nviewplane 10\n";

#[test]
fn an_ordinary_scene_prepares_in_every_type() {
    let text = std::format!("{CAMERA}light point 5 5 5\nshadows on\nsphere\nscale 2 2 2\ncube\ntranslate 3 0 0\n");
    assert_eq!(prepare::<f64>(&text), Ok(()));
    assert_eq!(prepare::<f32>(&text), Ok(()));
    assert_eq!(prepare::<Fixed>(&text), Ok(()));
    assert_eq!(prepare::<Fixed16>(&text), Ok(()));
    #[cfg(feature = "soft-float")]
    assert_eq!(prepare::<crate::number::SoftFloat>(&text), Ok(()));
}

#[test]
fn a_far_object_names_its_line_and_the_limit() {
    // 30 000 is beyond fixed's ±26 000 and fixed16's ±16 384; the floats take it.
    let text = std::format!("{CAMERA}sphere\ncube\n  translate 30000 0 0\n");
    assert_eq!(rejection::<Fixed>(&text).0, 5);
    assert_eq!(rejection::<Fixed16>(&text).0, 5);
    assert!(rejection::<Fixed>(&text).1.contains("bounding volume"));
    assert_eq!(prepare::<f32>(&text), Ok(()));
    assert_eq!(prepare::<f64>(&text), Ok(()));
    #[cfg(feature = "soft-float")]
    assert_eq!(prepare::<crate::number::SoftFloat>(&text), Ok(()));
    // 20 000 fits fixed but not fixed16.
    let text = std::format!("{CAMERA}sphere\n  translate 20000 0 0\n");
    assert_eq!(prepare::<Fixed>(&text), Ok(()));
    assert_eq!(rejection::<Fixed16>(&text).0, 4);
    // The message says what, for which type, and the documented range.
    let error = prepare::<Fixed>(&std::format!("{CAMERA}cube\n  scale 40000 1 1\n")).unwrap_err();
    let message = std::format!("{error}");
    assert!(message.starts_with("line 4: the object's bounding volume reaches 40000"), "{message}");
    assert!(message.contains("`fixed`") && message.contains("±26000"), "{message}");
}

#[test]
fn a_small_object_far_from_the_eye_is_too_large_in_its_own_space() {
    // A sphere of radius 0.001 at 100 units: the eye is 100 000 radii away (squares of that
    // saturate Q32.32); at 20 units it is 20 000 radii away, which fits.
    let far = "viewport 0 15 0 15\nwindow -1 1 -1 1\nviewplane 0\nperspective 0 0 100\nsphere\n  scale 0.001 0.001 0.001\n";
    let (line, what, value) = rejection::<Fixed>(far);
    assert_eq!(line, 5);
    assert!(what.contains("smallest scale"), "{what}");
    assert!((value - 100_000.0).abs() < 1.0, "{value}");
    assert_eq!(prepare::<f32>(far), Ok(()));
    let near = far.replace("perspective 0 0 100", "perspective 0 0 20");
    assert_eq!(prepare::<Fixed>(&near), Ok(()));
}

#[test]
fn shadow_rays_start_on_every_object() {
    // Without shadows only the eye matters; with shadows, the far cube's corners are ray
    // origins in the small sphere's space too.
    let text = "viewport 0 15 0 15\nwindow -1 1 -1 1\nviewplane 0\nperspective 0 0 10\nsphere\n  scale 0.001 0.001 0.001\ncube\n  translate 0 0 -25000\n";
    assert_eq!(prepare::<Fixed>(text), Ok(()));
    let with_shadows = std::format!("shadows on\n{text}");
    assert_eq!(rejection::<Fixed>(&with_shadows).0, 6);
}

#[test]
fn near_singular_transforms() {
    // One axis scaled by 1e-5: the inverse has an entry of 10^5.
    let text = std::format!("{CAMERA}cube\n  scale 1 1 0.00001\n");
    let (line, what, _) = rejection::<Fixed>(&text);
    assert_eq!(line, 4);
    assert!(what.contains("inverse"), "{what}");
    assert_eq!(prepare::<f32>(&text), Ok(()));
}

#[test]
fn camera_and_light_are_checked() {
    let window = "viewport 0 15 0 15\nwindow 29000 29001 0 1\nsphere\n";
    // Each error names the line of the statement that set the value.
    assert_eq!(rejection::<Fixed>(window), (2, "the window", 29001.0));
    let eye = "# the eye\nperspective 0 0 30000\nsphere\n";
    assert_eq!(rejection::<Fixed>(eye).0, 2);
    assert_eq!(rejection::<Fixed>(eye).1, "the eye");
    let light = "\n\nlight point 0 30000 0\nsphere\n";
    assert_eq!(rejection::<Fixed>(light).0, 3);
    assert_eq!(rejection::<Fixed>(light).1, "the light");
    assert_eq!(prepare::<f64>(light), Ok(()));
    let plane = "viewplane 1e20\nsphere\n";
    assert_eq!(rejection::<f32>(plane), (1, "the view plane distance", 1e20));
    // f64's range is ±10¹⁸ too (docs/fuzzing.md, finding 3).
    assert_eq!(rejection::<f64>(plane), (1, "the view plane distance", 1e20));
    assert_eq!(prepare::<f64>("viewplane 1e17\nsphere\n"), Ok(()));
}
