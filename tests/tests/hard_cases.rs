//! The hard cases (issue 4): every scene in `scenes/hard/` rendered in every number type and
//! compared with `f64`, pixel by pixel. For each case and type the test measures
//! - hit/miss flips (a pixel that is background in one and an object in the other),
//! - pixels whose palette index differs,
//! - NaNs (a non-finite ray parameter, normal or lighting term),
//! - the depth error of pixels that hit the same object (a wrap-around would show here),
//! - shadow acne: of the lit points (both types hit the same object there, both say it faces
//!   the light and `f64` finds no blocker), the share the type's shadow ray calls shadowed by a
//!   surface through the point itself (a blocker further away is a shadow's edge in a slightly
//!   different place, reported as `shadow edge`). The test also reports how many of those points the object's own surface would block if the
//!   tracer did not skip the shaded object (`self-blocked`), i.e. the acne that skip prevents.
//!
//! Targets: no panic, no NaN, no wrap; `f32` and `soft32` ≥ 99.95% identical pixels and no
//! acne; `fixed` no flips, ≥ 99.5% identical, no acne. A scene beyond a type's documented range
//! must be rejected at preparation with the range error instead. `fixed16` and `f32-micromath`
//! cannot meet the targets (nor `soft32` on two cases of exact ties); for them the test asserts
//! the measured bounds (with a small margin), listed per case below and in docs/hard-cases.md.
//! Run with `--nocapture` to see the measurements; `HARD_CASE_DEBUG=<file>:<type>` also lists
//! that case's differing pixels.

use microtrace::camera::PixelPosition;
use microtrace::geometry::{Ray, Vector3};
use microtrace::number::{F32Micro, Fixed, Fixed16, Number, SoftFloat};
use microtrace::model::{Primitive, SceneError, SceneErrorKind};
use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, ShadedPixel, Statistics, Whole, in_shadow, nearest_hit, shade_pixel, shadow_origin};
use microtrace::model::SceneDescription;
use microtrace::light::PreparedLight;
use microtrace::scene::Scene;
use microtrace::shapes::Interval;

const CAPACITY: usize = 16;

/// What one pixel's primary ray found, in `f64` for comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
struct PixelTrace {
    /// The object hit, if any.
    object: Option<usize>,
    t: f64,
    /// The hit faces the light (by the type's own normal).
    faces_light: bool,
    /// The type's shadow ray is blocked (only traced where the point faces the light).
    shadowed: bool,
    /// For a blocked shadow ray: the nearest blocker is so close to the point (within 10⁻³ of
    /// its magnitude) that its surface passes through the point: acne, not a shadow's edge.
    blocked_at_the_point: bool,
    /// The object's own surface blocks the shadow ray (what skipping the shaded object avoids).
    self_blocked: bool,
    finite: bool,
}

struct Rendering {
    indices: Vec<u8>,
    traces: Vec<PixelTrace>,
}

fn load(name: &str) -> SceneDescription<CAPACITY> {
    let path = format!("{}/../scenes/hard/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read(&path).unwrap_or_else(|error| panic!("{path}: {error}"));
    microtrace::parser::parse::<CAPACITY>(&text).unwrap_or_else(|error| panic!("{path}: {error}"))
}

fn finite3<N: Number>(v: Vector3<N>) -> bool {
    v.to_f64().iter().all(|c| c.is_finite())
}

/// The primary ray's hit and its shadow ray, as `render::trace` shades it.
fn trace_pixel<N: Number>(scene: &Scene<N, CAPACITY>, pixel: PixelPosition) -> PixelTrace {
    let mut statistics = Statistics::default();
    let miss = PixelTrace { object: None, t: 0.0, faces_light: false, shadowed: false, blocked_at_the_point: false, self_blocked: false, finite: true };
    let Some(ray) = scene.camera.primary_ray(pixel) else { return miss };
    let Some(hit) = nearest_hit(scene, &ray, pixel, &mut statistics) else {
        return PixelTrace { finite: finite3(ray.direction) && finite3(ray.origin), ..miss };
    };
    let object = &scene.objects[hit.object];
    let mut normal = object.object_from_world.transposed_vector(hit.local_normal).normalized().unwrap_or(-ray.direction);
    if normal.dot(ray.direction) > N::ZERO {
        normal = -normal;
    }
    let point = ray.at(hit.t);
    let (to_light, distance) = match scene.light {
        PreparedLight::Point(position) => {
            let offset = position - point;
            (offset.normalized().unwrap_or(normal), offset.length())
        }
        PreparedLight::Direction(direction) => (direction, N::MAX),
    };
    let faces_light = normal.dot(to_light) > N::ZERO;
    let shadowed = scene.shadows && faces_light && in_shadow(scene, hit.object, shadow_origin(point, normal), to_light, distance, &mut statistics);
    let origin = shadow_origin(point, normal);
    let nearest_blocker = scene
        .objects
        .iter()
        .enumerate()
        .filter(|(index, _)| shadowed && *index != hit.object)
        .filter_map(|(_, other)| other.primitive.intersect(&other.object_from_world.ray(&Ray { origin, direction: to_light }), Interval::below(distance)))
        .map(|blocker| blocker.t.to_f64())
        .fold(f64::INFINITY, f64::min);
    let magnitude = point.to_f64().iter().fold(1.0f64, |largest, c| largest.max(c.abs()));
    let blocked_at_the_point = nearest_blocker < 1e-3 * magnitude;
    let shadow_ray = Ray { origin: point, direction: to_light };
    let self_blocked = scene.shadows && faces_light && object.primitive.occluded(&object.object_from_world.ray(&shadow_ray), Interval::below(distance));
    let lighting_finite = match shade_pixel(scene, pixel, &mut statistics) {
        ShadedPixel::Background => true,
        ShadedPixel::Surface { lighting, .. } => lighting.diffuse.to_f64().is_finite() && lighting.specular.to_f64().is_finite(),
    };
    PixelTrace {
        object: Some(hit.object),
        t: hit.t.to_f64(),
        faces_light,
        shadowed,
        blocked_at_the_point,
        self_blocked,
        finite: hit.t.to_f64().is_finite() && finite3(normal) && finite3(point) && lighting_finite,
    }
}

fn render<N: Number>(description: &SceneDescription<CAPACITY>) -> Result<Rendering, SceneError> {
    let scene = Box::new(Scene::<N, CAPACITY>::prepare(description)?);
    let viewport = description.viewport;
    let (width, height) = (viewport.width(), viewport.height());
    let mut indices = vec![0u8; viewport.pixel_count() as usize];
    let mut frame = FrameBuffer::new(&mut indices, width, height).unwrap();
    microtrace::render::render(&scene, Pga, Whole, &mut frame, &mut Statistics::default());
    let mut traces = Vec::with_capacity(indices.len());
    for row in 0..height {
        for column in 0..width {
            traces.push(trace_pixel(&scene, scene.camera.pixel(column, row)));
        }
    }
    Ok(Rendering { indices, traces })
}

/// One type's image of one case against `f64`'s.
#[derive(Clone, Copy, Debug, Default)]
struct Measurement {
    pixels: usize,
    flips: usize,
    other_object: usize,
    identical: usize,
    not_finite: usize,
    /// Largest |t − t_f64| / max(1, t_f64) where both hit the same part of the same object.
    depth_error: f64,
    /// Pixels where both hit the same torus but on different parts of it (the depths more than
    /// 10⁻³ apart): a ray that grazes the tube in one type and passes it in the other, the
    /// non-convex object's own silhouette. Counted with the flips.
    other_part: usize,
    lit_points: usize,
    acne: usize,
    /// Lit points the type calls shadowed by a blocker away from the point: a shadow's edge
    /// in a slightly different place (counted in the identical share, not as acne).
    shadow_edge: usize,
    self_blocked: usize,
}

impl Measurement {
    /// `non_convex[i]`: object `i` is a torus.
    fn of(reference: &Rendering, image: &Rendering, non_convex: &[bool]) -> Self {
        let mut m = Measurement { pixels: reference.indices.len(), ..Default::default() };
        m.identical = reference.indices.iter().zip(&image.indices).filter(|(a, b)| a == b).count();
        for (expected, found) in reference.traces.iter().zip(&image.traces) {
            m.not_finite += usize::from(!found.finite);
            match (expected.object, found.object) {
                (Some(a), Some(b)) if a == b => {
                    let error = (found.t - expected.t).abs() / expected.t.max(1.0);
                    if error > 1e-3 && non_convex.get(a).copied().unwrap_or(false) {
                        m.other_part += 1;
                        m.flips += 1;
                        continue;
                    }
                    m.depth_error = m.depth_error.max(error);
                    if expected.faces_light && found.faces_light && !expected.shadowed {
                        m.lit_points += 1;
                        m.acne += usize::from(found.shadowed && found.blocked_at_the_point);
                        m.shadow_edge += usize::from(found.shadowed && !found.blocked_at_the_point);
                        m.self_blocked += usize::from(found.self_blocked);
                    }
                }
                (Some(_), Some(_)) => m.other_object += 1,
                (None, None) => {}
                _ => m.flips += 1,
            }
        }
        m
    }

    fn share(count: usize, total: usize) -> f64 {
        if total == 0 { 0.0 } else { count as f64 / total as f64 }
    }

    fn identical_share(&self) -> f64 {
        Self::share(self.identical, self.pixels)
    }

    fn flip_share(&self) -> f64 {
        Self::share(self.flips, self.pixels)
    }

    fn acne_share(&self) -> f64 {
        Self::share(self.acne, self.lit_points)
    }
}

/// Measured bounds for a type that cannot meet the targets: the most flips and acne and the
/// fewest identical pixels observed, with a small margin (fractions of 1).
#[derive(Clone, Copy, Debug)]
struct Bound {
    max_flips: f64,
    min_identical: f64,
    max_acne: f64,
    max_depth_error: f64,
}

const fn bound(max_flips: f64, min_identical: f64, max_acne: f64, max_depth_error: f64) -> Bound {
    Bound { max_flips, min_identical, max_acne, max_depth_error }
}

/// What each type must do on a case.
#[derive(Clone, Copy, Debug)]
enum Expect {
    /// The targets (f32: identical share; fixed: no flips, identical share); no acne.
    Targets,
    /// Rejected at preparation with the range error.
    Rejected,
    /// A measured bound.
    Measured(Bound),
}

struct Case {
    file: &'static str,
    f32: Expect,
    fixed: Expect,
    fixed16: Expect,
    micromath: Expect,
    /// `soft32` is held to `f32`'s targets.
    soft32: Expect,
}

use Expect::{Measured, Rejected, Targets};

/// The cases; fixed16 and f32-micromath bounds (and soft32's on the two tie cases) are the
/// measured worst with a margin.
const CASES: &[Case] = &[
    Case { file: "grazing_silhouettes.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.00149, 0.992, 0.0005, 0.0068)), micromath: Measured(bound(0.000653, 0.942, 0.0005, 0.166)), soft32: Targets },
    Case { file: "small_far_sphere_1e-3.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.00477, 0.755, 0.0005, 2.0)), micromath: Measured(bound(0.0005, 0.943, 0.0005, 0.001)), soft32: Targets },
    Case { file: "small_far_sphere_1e-4.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0345, 0.847, 0.0005, 2.0)), micromath: Measured(bound(0.0005, 0.798, 0.0005, 0.04)), soft32: Targets },
    Case { file: "large_coordinates.mts", f32: Targets, fixed: Targets, fixed16: Rejected, micromath: Measured(bound(0.0005, 0.965, 0.0005, 0.05)), soft32: Targets },
    Case { file: "small_beside_large.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0005, 0.918, 0.0005, 1.86)), micromath: Measured(bound(0.0005, 0.042, 0.0005, 0.05)), soft32: Targets },
    Case { file: "cylinder_parallel_axis.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0005, 0.994, 0.0005, 0.001)), micromath: Measured(bound(0.0005, 0.723, 0.0005, 0.001)), soft32: Targets },
    Case { file: "cone_parallel_side.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0005, 0.994, 0.0005, 0.001)), micromath: Measured(bound(0.0005, 0.93, 0.0005, 0.001)), soft32: Targets },
    Case { file: "cone_apex.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0005, 0.994, 0.0005, 0.001)), micromath: Measured(bound(0.0005, 0.945, 0.0005, 0.015)), soft32: Targets },
    Case { file: "cube_edges_corners.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.000575, 0.994, 0.0005, 0.001)), micromath: Measured(bound(0.0005, 0.978, 0.0005, 0.001)), soft32: Measured(bound(0.000125, 0.9985, 0.0005, 0.001)) },
    Case { file: "zero_direction_components.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.000653, 0.994, 0.0005, 0.001)), micromath: Measured(bound(0.0005, 0.989, 0.0005, 0.008)), soft32: Targets },
    Case { file: "eye_inside.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0005, 0.992, 0.0005, 0.0026)), micromath: Measured(bound(0.0005, 0.074, 0.0005, 1.1)), soft32: Targets },
    Case { file: "touching.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.000653, 0.993, 0.0005, 0.0022)), micromath: Measured(bound(0.0005, 0.898, 0.0005, 0.042)), soft32: Targets },
    Case { file: "interpenetrating.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.000958, 0.992, 0.0005, 0.0052)), micromath: Measured(bound(0.000653, 0.908, 0.0005, 0.038)), soft32: Targets },
    Case { file: "coincident.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0005, 0.994, 0.0005, 0.00108)), micromath: Measured(bound(0.0005, 0.863, 0.0005, 0.0138)), soft32: Targets },
    // fixed16 here: its rounded power-of-two interval scaling makes near-ties depend on the test
    // order; the bound is that of the render with no optimization, which every combination
    // gives since the capsule extents (the silhouette extents' order gave 97.4 % by chance).
    Case { file: "near_singular.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0195, 0.965, 0.0005, 2.0)), micromath: Measured(bound(0.0005, 0.98, 0.0005, 0.028)), soft32: Targets },
    Case { file: "specular_power.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0005, 0.994, 0.0005, 0.00172)), micromath: Measured(bound(0.0005, 0.938, 0.0005, 0.019)), soft32: Targets },
    Case { file: "far_from_origin.mts", f32: Targets, fixed: Targets, fixed16: Rejected, micromath: Measured(bound(0.0005, 0.922, 0.000712, 0.042)), soft32: Targets },
    // Exact ties under inexact transforms: decided by the last bit in every type (f64 too), so
    // measured for every type, f32 and fixed included (docs/hard-cases.md). soft32 is measured
    // on cube_edges_corners too: the rotated cube's edge lies exactly on a row of samples, so
    // which face a ray enters there is such a tie (f32 picks f64's face on half of that row,
    // soft32 on none of it: 15 pixels in all).
    Case { file: "exact_ties.mts", f32: Measured(bound(0.0055, 0.99, 0.0005, 0.001)), fixed: Measured(bound(0.0165, 0.981, 0.0005, 0.001)), fixed16: Measured(bound(0.0165, 0.98, 0.0005, 0.001)), micromath: Measured(bound(0.0055, 0.798, 0.0005, 0.001)), soft32: Measured(bound(0.0065, 0.992, 0.0005, 0.001)) },
    Case { file: "shadow_acne.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.000653, 0.983, 0.0005, 0.32)), micromath: Measured(bound(0.00103, 0.969, 0.0005, 0.104)), soft32: Targets },
    // The ring torus (§5.2.1): its quartic's failures in the textbook solvers (shapes/torus.rs).
    // The coarse types' flips are mostly the torus's other part: their depths differ from f64's
    // by more than 10⁻³ (their resolution), which on a non-convex object is counted as a flip.
    Case { file: "torus_grazing.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0025, 0.996, 0.0005, 0.002)), micromath: Measured(bound(0.25, 0.89, 0.0005, 0.002)), soft32: Targets },
    Case { file: "torus_inside_tube.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.27, 0.993, 0.0005, 0.002)), micromath: Measured(bound(0.97, 0.56, 0.0005, 0.005)), soft32: Targets },
    Case { file: "torus_axis_hole.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0025, 0.99, 0.0005, 0.002)), micromath: Measured(bound(0.15, 0.51, 0.0005, 0.002)), soft32: Targets },
    Case { file: "torus_large.mts", f32: Targets, fixed: Targets, fixed16: Rejected, micromath: Measured(bound(0.09, 0.945, 0.0005, 0.002)), soft32: Targets },
    // Solids whose operands share faces (CSG, thesis chapter 3): the rule for shared faces.
    // Q16.16 misses 19 pixels at the edges (its steps of 2⁻¹⁶ on t of about 200).
    Case { file: "csg_shared_faces.mts", f32: Targets, fixed: Targets, fixed16: Measured(bound(0.0015, 0.978, 0.0005, 0.15)), micromath: Measured(bound(0.0005, 0.94, 0.0005, 0.07)), soft32: Targets },
];

/// Renders `case` in `N`, checks what `expect` asks against the `f64` reference, and returns a
/// report line (or the failures).
fn check<N: Number>(file: &str, description: &SceneDescription<CAPACITY>, reference: &Rendering, expect: Expect, failures: &mut Vec<String>) -> String {
    let name = N::NAME;
    let rendering = match (render::<N>(description), expect) {
        (Err(SceneError { line, kind: SceneErrorKind::OutOfRangeForNumberType { number, limit, .. } }), Rejected) => {
            if number != name || limit != N::SCENE_LIMIT {
                failures.push(format!("{file} {name}: the error names {number} (±{limit})"));
            }
            return format!("{file:32} {name:14} rejected at preparation (line {line})");
        }
        (Err(error), _) => {
            failures.push(format!("{file} {name}: preparation failed: {error}"));
            return String::new();
        }
        (Ok(_), Rejected) => {
            failures.push(format!("{file} {name}: prepared, but the scene is beyond the type's range"));
            return String::new();
        }
        (Ok(rendering), _) => rendering,
    };
    let non_convex: Vec<bool> = description.objects.iter().map(|object| matches!(object.primitive, Primitive::Torus(_))).collect();
    let m = Measurement::of(reference, &rendering, &non_convex);
    // HARD_CASE_DEBUG=<file>:<type> lists that case's flipped pixels.
    if std::env::var("HARD_CASE_DEBUG").is_ok_and(|wanted| wanted == format!("{file}:{name}")) {
        let width = usize::from(description.viewport.width());
        for (index, (expected, found)) in reference.traces.iter().zip(&rendering.traces).enumerate() {
            if expected.object != found.object || expected.shadowed != found.shadowed || reference.indices[index] != rendering.indices[index] {
                println!("index f64 {} {name} {}", reference.indices[index], rendering.indices[index]);
                println!("pixel ({}, {}): f64 {expected:?}\n    {name} {found:?}", index % width, index / width);
            }
        }
    }
    let line = format!(
        "{file:32} {name:14} identical {:8.4}%  flips {:4} (torus's other part {})  other object {:4}  shadow edge {:3}  acne {:4}/{:5} ({:.4}%)  self-blocked {:5} ({:6.2}%)  depth error {:.1e}",
        m.identical_share() * 100.0,
        m.flips,
        m.other_part,
        m.other_object,
        m.shadow_edge,
        m.acne,
        m.lit_points,
        m.acne_share() * 100.0,
        m.self_blocked,
        Measurement::share(m.self_blocked, m.lit_points) * 100.0,
        m.depth_error,
    );
    let mut fail = |what: String| failures.push(format!("{file} {name}: {what}"));
    if m.not_finite > 0 {
        fail(format!("{} pixels not finite", m.not_finite));
    }
    match expect {
        Targets => {
            let target = if name == "fixed" { 0.995 } else { 0.9995 };
            if m.identical_share() < target {
                fail(format!("{:.4}% identical, target {:.2}%", m.identical_share() * 100.0, target * 100.0));
            }
            if m.acne > 0 {
                fail(format!("acne on {} of {} lit points", m.acne, m.lit_points));
            }
            if name == "fixed" && m.flips > 0 {
                fail(format!("{} hit/miss flips", m.flips));
            }
            // A wrap-around or a saturated intermediate would put the hit somewhere else.
            let depth_limit = if name == "fixed" || name == "f32" || name == "soft32" { 1e-3 } else { 0.0 };
            if m.depth_error > depth_limit && name != "f64" {
                fail(format!("depth error {:.1e}", m.depth_error));
            }
        }
        Measured(bound) => {
            let outside = m.flip_share() > bound.max_flips
                || m.identical_share() < bound.min_identical
                || m.acne_share() > bound.max_acne
                || m.depth_error > bound.max_depth_error;
            if outside {
                fail(format!("outside the measured bound {bound:?}: {line}"));
            }
        }
        Rejected => unreachable!(),
    }
    line
}

#[test]
fn hard_cases_in_every_number_type() {
    let mut failures = Vec::new();
    let mut report = Vec::new();
    for case in CASES {
        let description = load(case.file);
        let viewport = description.viewport;
        assert!(viewport.width() <= 129 && viewport.height() <= 129, "{}: keep the bench's scenes small", case.file);
        let reference = render::<f64>(&description).unwrap_or_else(|error| panic!("{}: {error}", case.file));
        // The scene is really there: objects cover a good share of the image.
        let hits = reference.traces.iter().filter(|trace| trace.object.is_some()).count();
        if hits * 10 < reference.traces.len() {
            failures.push(format!("{}: only {hits} pixels hit an object", case.file));
        }
        assert!(reference.traces.iter().all(|trace| trace.finite), "{}: f64 not finite", case.file);
        report.push(check::<f32>(case.file, &description, &reference, case.f32, &mut failures));
        report.push(check::<Fixed>(case.file, &description, &reference, case.fixed, &mut failures));
        report.push(check::<Fixed16>(case.file, &description, &reference, case.fixed16, &mut failures));
        report.push(check::<F32Micro>(case.file, &description, &reference, case.micromath, &mut failures));
        report.push(check::<SoftFloat>(case.file, &description, &reference, case.soft32, &mut failures));
    }
    for line in &report {
        println!("{line}");
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

/// Every scene file in `scenes/hard/` is one of the cases (the bench renders them all).
#[test]
fn every_hard_scene_is_a_case() {
    let directory = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/hard");
    let mut files: Vec<String> = std::fs::read_dir(directory)
        .unwrap()
        .map(|entry| entry.unwrap().file_name().into_string().unwrap())
        .filter(|name| name.ends_with(".mts"))
        .collect();
    files.sort();
    let mut cases: Vec<String> = CASES.iter().map(|case| case.file.to_owned()).collect();
    cases.sort();
    assert_eq!(files, cases);
    for file in &files {
        let text = std::fs::read_to_string(format!("{directory}/{file}")).unwrap();
        assert!(text.starts_with(&format!("# {file} -- ")), "{file}: starts with a comment saying what it stresses");
    }
}
