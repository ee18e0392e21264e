//! Constructive solid geometry (issue 23, thesis chapter 3) through the whole render: the rule
//! for coincident surfaces, and solids to shadow rays.
//!
//! **The rule.** Operands that share a face meet it at crossings a few units in the last place
//! apart, each computed in its own object space; boundaries closer than 2⁻¹⁶ of `t` are one
//! surface (`csg::spans::coincident`), the left operand's, so a face two operands share never
//! leaves a sliver of either. The test: a cube minus a pocket flush with its top face, and the
//! same with the pocket's cube reaching beyond the face (the textbook way to avoid the
//! coincidence, the exact answer), render identically at 256x256 in `f64` and `f32`.

use microtrace::model::SceneDescription;
use microtrace::number::Number;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, Statistics, Whole};
use microtrace::scene::Scene;

const CAPACITY: usize = 8;

fn render<N: Number>(text: &str) -> Vec<u8> {
    let description: SceneDescription<CAPACITY> = microtrace::parser::parse(text.as_bytes()).unwrap_or_else(|error| panic!("{error}"));
    let scene = Box::new(Scene::<N, CAPACITY>::prepare(&description).unwrap());
    let viewport = description.viewport;
    let mut pixels = vec![0u8; viewport.pixel_count() as usize];
    let mut frame = FrameBuffer::new(&mut pixels, viewport.width(), viewport.height()).unwrap();
    microtrace::render::render(&*scene, Pga, Whole, &mut frame, &mut Statistics::default());
    pixels
}

/// A block with a pocket cut into its top face (and a slot into its front face), seen from above
/// at an angle; `reach` doubles the cutting cubes' depth so that they stand out beyond the faces
/// (else they are flush). Doubling changes their inverse transforms by exact powers of two, so
/// every surface the picture shows is computed to the same bits: only the shared faces differ.
fn pocketed_block(reach: bool, rotation: f64) -> String {
    format!(
        "viewport 0 255 0 255\nwindow -60 60 -60 60\nviewplane 0\nperspective 30 140 160\nlight point -80 200 150\nshadows on\n\
         group 1 15 12 4 up\ngroup 2 4 9 15 up\nbackground 0\n\
         difference\n cube\n  scale 80 40 80\n  translate -40 -20 -40\n\
         cube\n  scale 40 {pocket} 40\n  translate -20 4 -20\n  colour 2\n\
         cube\n  scale 20 20 {slot}\n  translate -10 -10 8\n  colour 2\nend\n rotate y {rotation}\n colour 1\n",
        pocket = if reach { 32 } else { 16 },
        slot = if reach { 64 } else { 32 },
    )
}

fn flush_faces_render_as_the_exact_solid<N: Number>() {
    for rotation in [0.0, 17.0, 45.0] {
        let exact = render::<N>(&pocketed_block(true, rotation));
        let flush = render::<N>(&pocketed_block(false, rotation));
        let differing = exact.iter().zip(&flush).filter(|(a, b)| a != b).count();
        // The pocket and the slot are really there: their colour group shows.
        assert!(exact.iter().filter(|&&index| index / 16 == 2).count() > 1000, "{} rotation {rotation}: no pocket", N::NAME);
        assert_eq!(differing, 0, "{} rotation {rotation}: {differing} pixels differ from the exact solid", N::NAME);
    }
}

#[test]
fn flush_faces_render_as_the_exact_solid_in_f64() {
    flush_faces_render_as_the_exact_solid::<f64>();
}

#[test]
fn flush_faces_render_as_the_exact_solid_in_f32() {
    flush_faces_render_as_the_exact_solid::<f32>();
}

/// A shadow ray meets a solid where the solid is: under a ring (a cylinder minus a narrower
/// one), the floor is lit through the hole and shadowed under the wall, in every type; a
/// point inside a hollow is shadowed by the wall around it.
fn shadows_follow_the_solid<N: Number>() {
    use microtrace::geometry::Vector3;
    let text = "light direction 0 1 0\nshadows on\ncube\n  scale 100 1 100\n  translate -50 -1 -50\n\
                difference\n cylinder\n  scale 20 20 10\n  rotate x -90\n cylinder\n  scale 10 10 30\n  rotate x -90\n  translate 0 -10 0\nend\n  translate 0 30 0\n";
    let description: SceneDescription<CAPACITY> = microtrace::parser::parse(text.as_bytes()).unwrap();
    let scene = Scene::<N, CAPACITY>::prepare(&description).unwrap();
    let up = Vector3::from_f64([0.0, 1.0, 0.0]);
    let shadowed = |x: f64, y: f64| microtrace::render::in_shadow(&scene, 0, Vector3::from_f64([x, y, 0.0]), up, N::MAX, &mut Statistics::default());
    assert!(!shadowed(0.0, 0.0), "{}: the hole casts a shadow", N::NAME);
    assert!(!shadowed(9.0, 0.0), "{}: the hole's edge casts a shadow", N::NAME);
    assert!(shadowed(15.0, 0.0), "{}: the wall casts no shadow", N::NAME);
    assert!(shadowed(-19.0, 0.0), "{}: the wall casts no shadow", N::NAME);
    assert!(!shadowed(25.0, 0.0), "{}: beyond the ring is shadowed", N::NAME);
    // From inside the wall's material the ray leaves through the wall's top: blocked.
    assert!(shadowed(15.0, 35.0), "{}: inside the wall, no boundary met", N::NAME);
}

#[test]
fn shadows_follow_the_solid_in_every_type() {
    shadows_follow_the_solid::<f64>();
    shadows_follow_the_solid::<f32>();
    shadows_follow_the_solid::<microtrace::number::Fixed>();
    shadows_follow_the_solid::<microtrace::number::SoftFloat>();
}
