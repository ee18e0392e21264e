//! The key test of the optimizations (issue 3): every one of the 16 combinations renders a
//! bit-identical image to the unoptimized render, on both thesis scenes and on many generated
//! random scenes (all four primitives, arbitrary transforms, both projections in every
//! direction, eyes inside objects, both light types, shadows on and off), in f64 and f32, in
//! PGA and RGB mode. The generator is a fixed-seed xorshift, so a failure names its seed.

use microtrace::config::Arrays;
use microtrace::geometry::Matrix4;
use microtrace::number::{Fixed, Number};
use microtrace::optimize::bounding_volume::ObjectGeometry;
use microtrace::optimize::extents::Extent;
use microtrace::optimize::Acceleration;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, Rgb, Statistics, Whole};
use microtrace::model::{Light, Material, ObjectDescription, Optimizations, Primitive, Projection, SceneDescription, Tube, Viewport, Window};
use microtrace::scene::Scene;

const CAPACITY: usize = 64;

struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.unit()
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn direction(&mut self) -> [f64; 3] {
        loop {
            let v = [self.range(-1.0, 1.0), self.range(-1.0, 1.0), self.range(-1.0, 1.0)];
            let length = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            if length > 0.1 && length <= 1.0 {
                return v.map(|c| c / length);
            }
        }
    }
}

fn load(name: &str) -> SceneDescription<CAPACITY> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/").to_owned() + name;
    let text = std::fs::read(&path).unwrap();
    microtrace::parser::parse::<CAPACITY>(&text).unwrap_or_else(|error| panic!("{path}: {error}"))
}

#[derive(Debug, PartialEq)]
enum Image {
    Pga(Vec<u8>),
    Rgb(Vec<[u8; 3]>),
}

fn render<N: Number>(description: &SceneDescription<CAPACITY>, rgb: bool) -> (Image, Statistics) {
    let scene = Box::new(Scene::<N, CAPACITY>::prepare(description).unwrap());
    let viewport = description.viewport;
    let (width, height) = (viewport.width(), viewport.height());
    let mut statistics = Statistics::default();
    let count = viewport.pixel_count() as usize;
    let image = if rgb {
        let mut pixels = vec![[0u8; 3]; count];
        microtrace::render::render(&*scene, Rgb, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
        Image::Rgb(pixels)
    } else {
        let mut pixels = vec![0u8; count];
        microtrace::render::render(&*scene, Pga, Whole, &mut FrameBuffer::new(&mut pixels, width, height).unwrap(), &mut statistics);
        Image::Pga(pixels)
    };
    (image, statistics)
}

/// Renders every combination and compares with the unoptimized image; returns the all-on and
/// none statistics.
fn all_combinations_match<N: Number>(description: &SceneDescription<CAPACITY>, rgb: bool, label: &str) -> (Statistics, Statistics) {
    let mut scene = description.clone();
    scene.optimizations = Optimizations::NONE;
    let (reference, none) = render::<N>(&scene, rgb);
    let mut all = none;
    for optimizations in Optimizations::combinations().skip(1) {
        scene.optimizations = optimizations;
        let (image, statistics) = render::<N>(&scene, rgb);
        if image != reference {
            let differing = match (&image, &reference) {
                (Image::Pga(a), Image::Pga(b)) => a.iter().zip(b).position(|(x, y)| x != y),
                (Image::Rgb(a), Image::Rgb(b)) => a.iter().zip(b).position(|(x, y)| x != y),
                _ => None,
            };
            panic!("{label}, {} {}, {optimizations:?}: image differs from none (first pixel {differing:?})", N::NAME, if rgb { "rgb" } else { "pga" });
        }
        assert_eq!(statistics.pixels, none.pixels);
        assert_eq!(statistics.rays_intersected + (none.rays_traced - statistics.rays_traced), none.rays_intersected + (none.rays_traced - statistics.rays_traced));
        assert!(statistics.ro_tests <= none.ro_tests, "{label} {optimizations:?}: more tests than none");
        if optimizations == Optimizations::ALL {
            all = statistics;
        }
    }
    (all, none)
}

/// A generated scene's combinations in `f64` and `f32` (one in PGA, the other in RGB, by the
/// seed) and, every fourth seed, in Q32.32 (near the eye a ray's rounding matters most);
/// the all-on and none statistics in `f64`.
fn seeded_scene_matches(scene: &SceneDescription<CAPACITY>, seed: u64, label: &str) -> (Statistics, Statistics) {
    let rgb = seed % 2 == 1;
    let (all, none) = all_combinations_match::<f64>(scene, rgb, label);
    all_combinations_match::<f32>(scene, !rgb, label);
    if seed.is_multiple_of(4) && Scene::<Fixed, CAPACITY>::prepare(scene).is_ok() {
        all_combinations_match::<Fixed>(scene, rgb, label);
    }
    (all, none)
}

fn random_matrix(rng: &mut XorShift, centre: [f64; 3], size: f64) -> Matrix4 {
    let mut m = Matrix4::IDENTITY;
    // Centre the unit primitive, scale non-uniformly, rotate about random axes, place.
    m.translate([-0.5, -0.5, -0.5]);
    m.scale([rng.range(0.2, 1.0) * size, rng.range(0.2, 1.0) * size, rng.range(0.2, 1.0) * size]);
    for _ in 0..rng.below(4) {
        m.rotate(rng.below(3) as usize, rng.range(-180.0, 180.0));
    }
    m.translate(centre);
    m
}

fn random_scene(seed: u64) -> SceneDescription<CAPACITY> {
    let mut rng = XorShift(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let mut scene = SceneDescription::<CAPACITY>::default();
    let (width, height) = (12 + rng.below(30) as u16, 10 + rng.below(30) as u16);
    scene.viewport = Viewport { x1: rng.below(3) as u16, x2: 0, y1: rng.below(3) as u16, y2: 0 };
    scene.viewport.x2 = scene.viewport.x1 + width - 1;
    scene.viewport.y2 = scene.viewport.y1 + height - 1;
    let half = rng.range(2.0, 10.0);
    let (cx, cy) = (rng.range(-5.0, 5.0), rng.range(-5.0, 5.0));
    scene.window = Window { x1: cx - half, x2: cx + half, y1: cy - half * rng.range(0.5, 1.5), y2: cy + half };
    scene.view_plane = rng.range(-20.0, 20.0);
    let d = scene.view_plane;
    // Points the camera sees, to place objects around.
    let mut targets: Vec<[f64; 3]> = Vec::new();
    let kind = rng.below(6);
    if kind < 3 {
        let direction = match kind {
            0 => [0.0, 0.0, if rng.below(2) == 0 { -1.0 } else { 1.0 }],
            1 => [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), 0.0], // along the view plane (B17)
            _ => rng.direction(),
        };
        scene.projection = Projection::Parallel { direction };
        for _ in 0..8 {
            let s = rng.range(-3.0, 3.0 * half);
            let length = (direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]).sqrt().max(1e-9);
            let o = [rng.range(scene.window.x1, scene.window.x2), rng.range(scene.window.y1, scene.window.y2), d];
            targets.push([0, 1, 2].map(|k| o[k] + direction[k] / length * s));
        }
    } else {
        let eye = [rng.range(-5.0, 5.0), rng.range(-5.0, 5.0), d + rng.range(-30.0, 30.0)];
        scene.projection = Projection::Perspective { eye };
        for _ in 0..8 {
            let o = [rng.range(scene.window.x1, scene.window.x2), rng.range(scene.window.y1, scene.window.y2), d];
            let s = rng.range(-0.3, 3.0);
            targets.push([0, 1, 2].map(|k| eye[k] + (o[k] - eye[k]) * s));
        }
        // Sometimes an object around the eye itself.
        if rng.below(4) == 0 {
            targets.push(eye);
        }
    }
    let count = 1 + rng.below(10) as usize;
    for i in 0..count {
        let primitive = match Primitive::ALL[rng.below(Primitive::ALL.len() as u64) as usize] {
            // Tori of any tube, thin to fat.
            Primitive::Torus(_) => Primitive::Torus(Tube::from_f64(rng.range(0.05, 0.95)).unwrap()),
            other => other,
        };
        let mut object = ObjectDescription::new(primitive, i as u32 + 1);
        let centre = targets[rng.below(targets.len() as u64) as usize];
        let jitter = half * 0.3;
        let centre = centre.map(|c| c + rng.range(-jitter, jitter));
        let size = half * rng.range(0.2, 1.2);
        object.world_from_object = random_matrix(&mut rng, centre, size);
        object.material = Material {
            colour: rng.below(16) as u8,
            ka: rng.range(0.0, 1.0),
            kd: rng.range(0.0, 1.0),
            ks: rng.range(0.0, 1.0),
            pwr: rng.range(1.0, 50.0),
            rnd: rng.range(0.0, 2.0),
            cmy: [rng.unit(), rng.unit(), rng.unit()],
            ..Material::default()
        };
        scene.objects.push(object).unwrap();
    }
    // Sometimes two identical objects: exact ties in t, which go to the lower object number.
    if rng.below(4) == 0 {
        let copy = scene.objects[0];
        let _ = scene.objects.push(copy);
    }
    scene.light = if rng.below(2) == 0 {
        Light::Point(targets[0].map(|c| c + rng.range(-2.0 * half, 2.0 * half)))
    } else {
        Light::Direction(rng.direction())
    };
    scene.shadows = rng.below(3) != 0;
    scene.dither = rng.below(2) == 0;
    scene
}

/// A perspective scene whose objects reach the eye plane (digest B16, where the silhouettes are
/// clipped): a ground slab under (or over, or beside) the eye reaching far behind it, rods
/// passing beside the eye through its plane, and a few objects straddling that plane.
fn eye_plane_scene(seed: u64) -> SceneDescription<CAPACITY> {
    let mut rng = XorShift(seed.wrapping_mul(0xD1B5_4A32_D192_ED03) | 1);
    let mut scene = SceneDescription::<CAPACITY>::default();
    let (width, height) = (12 + rng.below(30) as u16, 10 + rng.below(30) as u16);
    scene.viewport = Viewport { x1: 0, x2: width - 1, y1: 0, y2: height - 1 };
    let half = rng.range(1.0, 6.0);
    let (cx, cy) = (rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
    scene.window = Window { x1: cx - half, x2: cx + half, y1: cy - half * rng.range(0.5, 1.5), y2: cy + half };
    scene.view_plane = rng.range(-20.0, 20.0);
    let span = if rng.below(2) == 0 { rng.range(2.0, 15.0) } else { -rng.range(2.0, 15.0) };
    let eye = [rng.range(-3.0, 3.0), rng.range(-3.0, 3.0), scene.view_plane - span];
    scene.projection = Projection::Perspective { eye };
    let along = |s: f64, o: [f64; 2]| [eye[0] + (o[0] - eye[0]) * s, eye[1] + (o[1] - eye[1]) * s, eye[2] + span * s];
    let material = |rng: &mut XorShift| Material {
        colour: rng.below(16) as u8,
        ka: rng.range(0.0, 1.0),
        kd: rng.range(0.0, 1.0),
        ks: rng.range(0.0, 1.0),
        pwr: rng.range(1.0, 50.0),
        rnd: rng.range(0.0, 2.0),
        cmy: [rng.unit(), rng.unit(), rng.unit()],
        ..Material::default()
    };
    let push = |scene: &mut SceneDescription<CAPACITY>, primitive: Primitive, m: Matrix4, rng: &mut XorShift| {
        let mut object = ObjectDescription::new(primitive, scene.objects.len() as u32 + 1);
        object.world_from_object = m;
        object.material = material(rng);
        let _ = scene.objects.push(object);
    };
    // The ground: a thin slab at some height off the eye, tilted a little, reaching both ways.
    if rng.below(4) != 0 {
        let mut m = Matrix4::IDENTITY;
        m.translate([-0.5, -0.5, -1.0]);
        m.scale([rng.range(20.0, 200.0), rng.range(20.0, 200.0), rng.range(0.01, 1.0)]);
        m.rotate(0, 90.0 + rng.range(-20.0, 20.0));
        m.rotate(2, if rng.below(3) == 0 { rng.range(-180.0, 180.0) } else { rng.range(-10.0, 10.0) });
        m.translate([eye[0] + rng.range(-3.0, 3.0), eye[1] - rng.range(0.2, 3.0) * half / span.abs().max(1.0) * 5.0, eye[2] + rng.range(-5.0, 5.0)]);
        push(&mut scene, Primitive::Cube, m, &mut rng);
    }
    // Rods and cones through the eye plane, beside the eye.
    for _ in 0..rng.below(5) {
        let mut m = Matrix4::IDENTITY;
        let radius = rng.range(0.05, 1.0);
        m.scale([radius, radius, rng.range(5.0, 60.0)]);
        m.translate([0.0, 0.0, -0.5 * m.rows[2][2]]);
        m.rotate(0, rng.range(-60.0, 60.0));
        m.rotate(1, rng.range(-60.0, 60.0));
        let beside = [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
        let distance = rng.range(radius * 1.5, 8.0);
        let length = (beside[0] * beside[0] + beside[1] * beside[1]).sqrt().max(1e-3);
        m.translate([eye[0] + beside[0] / length * distance, eye[1] + beside[1] / length * distance, eye[2] + rng.range(-2.0, 2.0)]);
        let primitive = if rng.below(3) == 0 { Primitive::Cone } else { Primitive::Cylinder };
        push(&mut scene, primitive, m, &mut rng);
    }
    // Objects of any kind around the eye plane, and some in view.
    for _ in 0..1 + rng.below(5) {
        let primitive = Primitive::ALL[rng.below(Primitive::ALL.len() as u64) as usize];
        let o = [rng.range(scene.window.x1, scene.window.x2), rng.range(scene.window.y1, scene.window.y2)];
        let s = if rng.below(2) == 0 { rng.range(-0.2, 0.3) } else { rng.range(0.5, 3.0) };
        let mut centre = along(s, o);
        centre[0] += rng.range(-half, half);
        centre[1] += rng.range(-half, half);
        let size = half * rng.range(0.3, 2.0);
        let m = random_matrix(&mut rng, centre, size);
        push(&mut scene, primitive, m, &mut rng);
    }
    scene.light = if rng.below(2) == 0 { Light::Point(along(rng.range(0.5, 2.0), [cx, cy + half])) } else { Light::Direction(rng.direction()) };
    scene.shadows = rng.below(3) != 0;
    scene.dither = rng.below(2) == 0;
    scene
}

/// Objects reaching the eye plane (grounds, rods, objects around the eye): every combination
/// renders as none (f64, f32, and every fourth scene in Q32.32), and most such objects are
/// clipped, not the whole screen.
#[test]
fn eye_plane_scenes_render_identically_under_every_combination() {
    let seeds = std::env::var("MICROTRACE_SEEDS").ok().and_then(|text| text.parse().ok()).unwrap_or(300u64) / 3;
    let (mut tests_all, mut tests_none) = (0u64, 0u64);
    let (mut reaching, mut clipped) = (0usize, 0usize);
    for seed in 0..seeds {
        let scene = eye_plane_scene(seed);
        let label = format!("eye-plane scene seed {seed}");
        // How many objects' volumes straddle the eye plane, and how many of those are clipped
        // (an extent short of the whole screen).
        let prepared = Box::new(Scene::<f64, CAPACITY>::prepare(&scene).unwrap());
        let screen = prepared.acceleration.screen();
        let Projection::Perspective { eye } = scene.projection else { unreachable!() };
        let depth = |p: &[f64; 3]| (p[2] - eye[2]) / (scene.view_plane - eye[2]);
        for (index, object) in prepared.objects.iter().enumerate() {
            let volume = ObjectGeometry::new(object.primitive, &object.object_from_world).unwrap().volume();
            if volume.iter().any(|p| depth(p) <= 0.0) && volume.iter().any(|p| depth(p) > 0.0) {
                reaching += 1;
                clipped += usize::from(prepared.acceleration.extent(index) != Some(Extent::whole(screen)));
            }
        }
        let (all, none) = seeded_scene_matches(&scene, seed, &label);
        tests_all += all.ro_tests;
        tests_none += none.ro_tests;
    }
    println!("{seeds} eye-plane scenes: {tests_all} tests all-on against {tests_none} with none; {clipped} of {reaching} objects through the eye plane clipped");
    assert!(clipped * 2 > reaching, "{clipped} of {reaching} objects through the eye plane clipped");
    assert!(tests_all * 2 < tests_none, "the optimizations skip too little");
}

#[test]
fn random_scenes_render_identically_under_every_combination() {
    let started = std::time::Instant::now();
    let (mut tests_all, mut tests_none) = (0u64, 0u64);
    // MICROTRACE_SEEDS=N runs more scenes (the default keeps the test near a second).
    let seeds = std::env::var("MICROTRACE_SEEDS").ok().and_then(|text| text.parse().ok()).unwrap_or(300u64);
    for seed in 0..seeds {
        let scene = random_scene(seed);
        let label = format!("random scene seed {seed}");
        let rgb = seed % 2 == 1;
        let (all, none) = all_combinations_match::<f64>(&scene, rgb, &label);
        all_combinations_match::<f32>(&scene, !rgb, &label);
        tests_all += all.ro_tests;
        tests_none += none.ro_tests;
    }
    println!("{seeds} random scenes in {:.1?}: {tests_all} tests all-on against {tests_none} with none", started.elapsed());
    assert!(tests_all < tests_none, "the optimizations never skip anything");
}

#[test]
fn thesis_scenes_at_132x120_render_identically_under_every_combination() {
    // And the torus scene (scenes/torus.mts), whose table fills most of the picture: there the
    // optimizations save about half the tests (asserted: some), not the thesis scenes' four fifths.
    for (name, saving) in [("snooker.mts", 5), ("lattice.mts", 5), ("torus.mts", 1)] {
        let mut scene = load(name);
        scene.fit_to_size(132, 120);
        for rgb in [false, true] {
            let (all, none) = all_combinations_match::<f64>(&scene, rgb, name);
            assert!(all.ro_tests * saving < none.ro_tests, "{name}: all-on saves too little: {all:?} vs {none:?}");
            all_combinations_match::<f32>(&scene, rgb, name);
        }
    }
}

/// The coarse types too (deviation 30: the culls whose bounds do not hold there are off).
/// Before, 105 (`fixed16`) and 211 (`f32-micromath`) pixels of the lattice here differed
/// from `--opt none`, as fuzzing found.
#[test]
fn thesis_scenes_at_132x120_render_identically_in_fixed16_and_micromath() {
    for name in ["snooker.mts", "lattice.mts"] {
        let mut scene = load(name);
        scene.fit_to_size(132, 120);
        all_combinations_match::<microtrace::number::Fixed16>(&scene, false, name);
        all_combinations_match::<microtrace::number::F32Micro>(&scene, false, name);
    }
}

#[test]
fn thesis_scenes_at_full_size_all_on_matches_none() {
    for name in ["snooker.mts", "lattice.mts"] {
        let mut scene = load(name);
        scene.optimizations = Optimizations::NONE;
        let (reference, none) = render::<f64>(&scene, false);
        scene.optimizations = Optimizations::ALL;
        let (image, all) = render::<f64>(&scene, false);
        assert!(image == reference, "{name}: all-on differs from none at full size");
        let prepared = Box::new(Scene::<f64, CAPACITY>::prepare(&scene).unwrap());
        assert!(prepared.acceleration.grid_active(), "{name}: the grid pool overflowed");
        println!("{name}: {} grid entries for {} objects", prepared.acceleration.grid_entries(), scene.objects.len());
        assert_eq!(all.rays_intersected, none.rays_intersected);
        assert_eq!(all.shadow_rays, none.shadow_rays);
        println!("{name}: none {none:?}\n{name}: all  {all:?}");
    }
}

#[test]
fn acceleration_memory_is_bounded() {
    let per_scene_54 = core::mem::size_of::<Acceleration<Arrays<f64, 54>>>();
    let per_scene_21 = core::mem::size_of::<Acceleration<Arrays<f64, 21>>>();
    let per_object = (per_scene_54 - per_scene_21) as f64 / 33.0;
    let fixed = per_scene_21 as f64 - 21.0 * per_object;
    let f32_54 = core::mem::size_of::<Acceleration<Arrays<f32, 54>>>();
    println!("Acceleration<Arrays<f64, N>>: {per_object} bytes per object + {fixed} bytes per scene; f64 x 54 = {per_scene_54}, f32 x 54 = {f32_54}");
    assert!(per_object <= 450.0, "{per_object} bytes per object");
    // Per scene: the screen, the grid's cell starts, and the handles of the tables a firmware
    // scene holds in flash (the grid's, the hierarchy's, the shadow tables', the view's six
    // slices: 112 bytes of them on a 64-bit host, 56 on the chip, whose whole scene is 1,128).
    assert!(fixed <= 1152.0, "{fixed} bytes per scene");
}

/// The CSG scenes (scenes/csg/): a solid is one object to the optimizations, through the box
/// that encloses it (§3.3.6), so every combination gives the unoptimized image, in every type.
#[test]
fn csg_scenes_at_132x120_render_identically_under_every_combination() {
    for name in ["csg/die.mts", "csg/lens.mts", "csg/cup.mts", "csg/nut.mts"] {
        let mut scene = load(name);
        scene.fit_to_size(132, 120);
        let (all, none) = all_combinations_match::<f64>(&scene, false, name);
        println!("{name}: {} tests all-on against {} with none", all.ro_tests, none.ro_tests);
        assert!(all.ro_tests < none.ro_tests, "{name}: the optimizations skip nothing");
        all_combinations_match::<f64>(&scene, true, name);
        all_combinations_match::<f32>(&scene, false, name);
        all_combinations_match::<Fixed>(&scene, false, name);
        all_combinations_match::<microtrace::number::SoftFloat>(&scene, false, name);
    }
}

/// A random scene whose first objects become solids: each the first object's primitive with
/// one to three more near it under random operations (nested when there are three), so that
/// their boxes overlap, touch, nest or miss.
fn random_solid_scene(seed: u64) -> SceneDescription<CAPACITY> {
    use microtrace::model::{enclosing_transform, Operation, SolidNode, SolidRange};
    let mut scene = random_scene(seed);
    let mut rng = XorShift(seed.wrapping_mul(0x2545_F491_4F6C_DD1D) | 1);
    let solids = 1 + rng.below(2) as usize;
    for index in 0..solids.min(scene.objects.len()) {
        let first = scene.solids.len();
        let base = scene.objects[index];
        let half = (scene.window.x2 - scene.window.x1) / 2.0;
        let centre = base.world_from_object.transform_point([0.5; 3]);
        scene.solids.push(SolidNode::Leaf(base)).unwrap();
        let operands = 1 + rng.below(3) as usize;
        let operations = [Operation::Union, Operation::Intersection, Operation::Difference];
        for operand in 0..operands {
            let primitive = match Primitive::ALL[rng.below(Primitive::ALL.len() as u64) as usize] {
                Primitive::Torus(_) => Primitive::Torus(Tube::from_f64(rng.range(0.1, 0.9)).unwrap()),
                other => other,
            };
            let mut leaf = ObjectDescription::new(primitive, base.line);
            let centre = centre.map(|c| c + rng.range(-0.3 * half, 0.3 * half));
            let size = half * rng.range(0.2, 1.0);
            leaf.world_from_object = random_matrix(&mut rng, centre, size);
            // Some operands keep the solid's material, others have their own.
            if rng.below(2) == 0 {
                leaf.material.colour = rng.below(16) as u8;
            } else {
                leaf.material = base.material;
            }
            scene.solids.push(SolidNode::Leaf(leaf)).unwrap();
            // Two operands after the first: the last two nest under their own operation.
            if operands == 3 && operand == 1 {
                continue;
            }
            if operands == 3 && operand == 2 {
                scene.solids.push(SolidNode::Combine { operation: operations[rng.below(3) as usize], line: 0 }).unwrap();
            }
            scene.solids.push(SolidNode::Combine { operation: operations[rng.below(3) as usize], line: 0 }).unwrap();
        }
        let range = SolidRange { first: first as u16, count: (scene.solids.len() - first) as u16 };
        let object = &mut scene.objects[index];
        object.primitive = Primitive::Solid(range);
        object.world_from_object = enclosing_transform(&scene.solids[range.nodes()], object.line).unwrap();
    }
    scene
}

#[test]
fn random_solid_scenes_render_identically_under_every_combination() {
    let (mut tests_all, mut tests_none) = (0u64, 0u64);
    let seeds = std::env::var("MICROTRACE_SEEDS").ok().and_then(|text| text.parse().ok()).unwrap_or(300u64) / 2;
    for seed in 0..seeds {
        let scene = random_solid_scene(seed);
        let label = format!("random solid scene seed {seed}");
        let (all, none) = seeded_scene_matches(&scene, seed, &label);
        tests_all += all.ro_tests;
        tests_none += none.ro_tests;
    }
    println!("{seeds} random solid scenes: {tests_all} tests all-on against {tests_none} with none");
    assert!(tests_all < tests_none, "the optimizations never skip anything");
}
