//! A scene built in code is held to the format's ranges, as a parsed one is
//! (`Description::validate`, called by preparation): the same messages as the parser's, without
//! a line; and no description, however wrong, makes preparation or the render panic.
// Tests may unwrap (the core's own code may not).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use microtrace::model::{Antialias, Light, Projection, SceneDescription, SceneErrorKind, Viewport, Window};
use microtrace::pixel::FrameBuffer;
use microtrace::render::{render, Pga, Statistics, Whole};
use microtrace::scene::Scene;

const TEXT: &[u8] = b"viewport 0 31 0 15\nwindow -2 2 -1 1\nviewplane 0\nperspective 0 0 10\nlight point 2 10 5\nsphere\n  colour 2\ncube\n  translate 1 0 -2\n";

fn scene() -> SceneDescription<4> {
    microtrace::parser::parse(TEXT).unwrap()
}

/// The message preparation gives for `change`d, and the parser's for `text` (its statement
/// added to the scene's text), without the parser's line.
fn both(change: impl FnOnce(&mut SceneDescription<4>), statement: &str) -> (String, String) {
    let mut description = scene();
    change(&mut description);
    let prepared = Scene::<f32, 4>::prepare(&description).unwrap_err();
    let mut text = TEXT.to_vec();
    text.extend_from_slice(statement.as_bytes());
    let parsed = microtrace::parser::parse::<4>(&text).unwrap_err();
    (prepared.kind.to_string(), parsed.kind.to_string())
}

#[test]
fn a_description_built_in_code_is_refused_as_its_text_would_be() {
    type Change = fn(&mut SceneDescription<4>);
    let cases: [(Change, &str); 6] = [
        (|d| d.objects[1].material.colour = 15 + 185, "colour 200\n"),
        (|d| d.objects[1].material.reflect = 5.0, "reflect 5\n"),
        (|d| d.objects[1].material.ior = -1.0, "ior -1\n"),
        (|d| d.objects[1].material.kd = -0.5, "kd -0.5\n"),
        (|d| d.depth = 50, "depth 50\n"),
        (|d| d.ambient = -1.0, "ambient -1\n"),
    ];
    for (change, statement) in cases {
        let (prepared, parsed) = both(change, statement);
        assert_eq!(prepared, parsed, "{statement}");
    }
}

#[test]
fn a_nan_and_inverted_rectangles_are_refused() {
    let refused = |change: fn(&mut SceneDescription<4>)| {
        let mut description = scene();
        change(&mut description);
        Scene::<f32, 4>::prepare(&description).unwrap_err().kind
    };
    assert!(matches!(refused(|d| d.objects[0].material.kd = f64::NAN), SceneErrorKind::ValueOutOfRange { what: "kd", .. }));
    assert!(matches!(refused(|d| d.window = Window { x1: 2.0, x2: -2.0, y1: -1.0, y2: 1.0 }), SceneErrorKind::InvalidRectangle { what: "window", .. }));
    assert!(matches!(refused(|d| d.viewport = Viewport { x1: 31, x2: 0, y1: 0, y2: 15 }), SceneErrorKind::InvalidRectangle { what: "viewport", .. }));
    assert!(matches!(refused(|d| d.light = Light::Direction([0.0; 3])), SceneErrorKind::ZeroDirection));
    assert!(matches!(refused(|d| d.projection = Projection::Perspective { eye: [f64::INFINITY, 0.0, 0.0] }), SceneErrorKind::NumberNotFinite { .. }));
    assert!(matches!(refused(|d| d.antialias = Some(Antialias { threshold: 0.1, levels: 9 })), SceneErrorKind::IntegerOutOfRange { what: "antialias L", .. }));
    assert!(matches!(refused(|d| d.palette.entries[3].g = 16), SceneErrorKind::IntegerOutOfRange { .. }));
    assert!(matches!(refused(|d| d.objects[0].world_from_object.rows[0][0] = f64::NAN), SceneErrorKind::SingularTransform));
    // An inverted viewport's size is never an overflow.
    assert_eq!(Viewport { x1: 31, x2: 0, y1: 5, y2: 1 }.width(), 1);
    assert_eq!(Viewport { x1: 0, x2: u16::MAX, y1: 0, y2: 0 }.width(), u16::MAX);
}

/// A small generator (xorshift), so the property test needs no dependency and repeats exactly.
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    /// A value that is often in range, often just outside, sometimes absurd.
    fn real(&mut self) -> f64 {
        match self.below(8) {
            0 => f64::NAN,
            1 => f64::INFINITY,
            2 => -f64::INFINITY,
            3 => -1.0,
            4 => 1.0e300,
            5 => 0.0,
            _ => (self.below(2001) as f64 - 1000.0) / 100.0,
        }
    }
}

#[test]
fn no_description_makes_preparation_or_the_render_panic() {
    let mut random = Random(0x9E37_79B9_7F4A_7C15);
    let mut refused = 0;
    for _ in 0..4000 {
        let mut d = scene();
        for _ in 0..1 + random.below(3) {
            match random.below(16) {
                0 => d.viewport = Viewport { x1: random.below(40) as u16, x2: random.below(40) as u16, y1: random.below(20) as u16, y2: random.below(20) as u16 },
                1 => d.window = Window { x1: random.real(), x2: random.real(), y1: random.real(), y2: random.real() },
                2 => d.view_plane = random.real(),
                3 => d.projection = Projection::Perspective { eye: [random.real(), random.real(), random.real()] },
                4 => d.projection = Projection::Parallel { direction: [random.real(), random.real(), random.real()] },
                5 => d.light = Light::Point([random.real(), random.real(), random.real()]),
                6 => d.light = Light::Direction([random.real(), random.real(), random.real()]),
                7 => d.light_intensity = random.real(),
                8 => d.depth = random.below(256) as u8,
                9 => d.antialias = Some(Antialias { threshold: random.real(), levels: random.below(8) as u8 }),
                10 => d.ambient = random.real(),
                11 => d.objects[0].material.colour = random.below(256) as u8,
                12 => d.objects[1].material.kd = random.real(),
                13 => d.objects[0].material.ior = random.real(),
                14 => d.objects[1].world_from_object.rows[random.below(3) as usize][random.below(4) as usize] = random.real(),
                _ => d.background = random.below(256) as u8,
            }
        }
        match Scene::<f32, 4>::prepare(&d) {
            Err(_) => refused += 1,
            Ok(prepared) => {
                let viewport = prepared.viewport();
                let (width, height) = (viewport.width(), viewport.height());
                let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
                let mut frame = FrameBuffer::new(&mut pixels, width, height).unwrap();
                render(&prepared, Pga, Whole, &mut frame, &mut Statistics::default());
            }
        }
    }
    // Both kinds were tried: some refused, some rendered.
    assert!((100..3900).contains(&refused), "{refused} of 4000 refused");
}
