//! The number types against `f64`: arithmetic accuracy over the tracer's ranges, saturation at
//! the extremes, the trait's edge cases, a ray–sphere accuracy mini-benchmark, and (when the
//! parser is in) whole thesis scenes at 128x64 against the `f64` rendering.
//!
//! Run with `--nocapture` to see the tables.

// A test: Cargo.toml's denial of unwrap/expect/panic is for the core's own code.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use microtrace::number::Number;
#[cfg(feature = "micromath")]
use microtrace::number::F32Micro;
#[cfg(feature = "fixed-point")]
use microtrace::number::{Fixed, Fixed16};
#[cfg(feature = "soft-float")]
use microtrace::number::SoftFloat;

/// Deterministic xorshift64* generator.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn range(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.unit()
    }
}

/// How close a type's operations must be to `f64` on the same (converted) inputs:
/// `|error| ≤ absolute + relative·|exact|`.
#[derive(Clone, Copy, Debug)]
struct Tolerance {
    absolute: f64,
    relative: f64,
    sqrt_relative: f64,
}

fn n<N: Number>(value: f64) -> N {
    N::from_f64(value)
}

fn within(got: f64, exact: f64, absolute: f64, relative: f64) -> bool {
    (got - exact).abs() <= absolute + relative * exact.abs()
}

/// The value ranges the tracer computes in: world positions (snooker in millimetres), unit
/// vector components, object-space directions (unit / radius), shading values.
const RANGES: [(f64, f64); 5] = [(-2000.0, 2000.0), (-1.0, 1.0), (-0.04, 0.04), (0.0, 15.0), (-60.0, 60.0)];

/// Checks +, −, ×, ÷, √ of `N` against `f64` on `N`'s own values. A result outside `N`'s range
/// must saturate to ±MAX (or its neighbour −MAX−1 for two's complement types).
fn check_arithmetic<N: Number>(tolerance: Tolerance) {
    let max = N::MAX.to_f64();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut worst = [0.0f64; 5];
    for _ in 0..200_000 {
        let (ra, rb) = (RANGES[(rng.next_u64() % 5) as usize], RANGES[(rng.next_u64() % 5) as usize]);
        let a: N = n(rng.range(ra.0, ra.1));
        let b: N = n(rng.range(rb.0, rb.1));
        let (x, y) = (a.to_f64(), b.to_f64());
        let mut check = |op: usize, got: N, exact: f64, relative: f64| {
            let got = got.to_f64();
            if exact.abs() > max {
                assert!(got.abs() >= max && got.signum() == exact.signum(), "{} op {op}: {x} {y}: {got} should saturate", N::NAME);
            } else {
                assert!(within(got, exact, tolerance.absolute, relative), "{} op {op}: {x}, {y}: got {got}, exact {exact}", N::NAME);
                worst[op] = worst[op].max((got - exact).abs() / (tolerance.absolute + relative * exact.abs()));
            }
        };
        check(0, a + b, x + y, tolerance.relative);
        check(1, a - b, x - y, tolerance.relative);
        check(2, a * b, x * y, tolerance.relative);
        if let Some(q) = a.checked_div(b) {
            check(3, q, x / y, tolerance.relative);
        } else {
            assert_eq!(y, 0.0);
        }
        check(4, a.abs().sqrt(), x.abs().sqrt(), tolerance.sqrt_relative);
    }
    println!("{:>14}: worst error / tolerance for + - * / sqrt: {worst:.3?}", N::NAME);
}

const F64_TOLERANCE: Tolerance = Tolerance { absolute: 0.0, relative: 1.2e-16, sqrt_relative: 1.2e-16 };
const F32_TOLERANCE: Tolerance = Tolerance { absolute: 1e-44, relative: 6e-8, sqrt_relative: 6e-8 };
/// Q32.32: half an LSB for + − × ÷ (exact for + −), the square root within 2⁻³¹ relative.
const FIXED_TOLERANCE: Tolerance = Tolerance { absolute: 0.500_001 / 4_294_967_296.0, relative: 1e-15, sqrt_relative: 4.7e-10 };
/// Q16.16: half an LSB, the square root within one LSB (it is floored).
const FIXED16_TOLERANCE: Tolerance = Tolerance { absolute: 1.0 / 65_536.0, relative: 1e-15, sqrt_relative: 1e-15 };
/// micromath's square root: up to 6.1 % (precision notes).
const MICROMATH_TOLERANCE: Tolerance = Tolerance { absolute: 1e-44, relative: 6e-8, sqrt_relative: 0.062 };
/// soft32: 28-bit mantissa; additions faithful (within one unit in the last place, 2⁻²⁷), the
/// rest rounded to nearest (2⁻²⁸).
#[cfg(feature = "soft-float")]
const SOFT32_TOLERANCE: Tolerance = Tolerance { absolute: 1e-300, relative: 7.46e-9, sqrt_relative: 3.73e-9 };

#[test]
fn arithmetic_matches_f64_within_tolerance() {
    check_arithmetic::<f64>(F64_TOLERANCE);
    check_arithmetic::<f32>(F32_TOLERANCE);
    #[cfg(feature = "fixed-point")]
    {
        check_arithmetic::<Fixed>(FIXED_TOLERANCE);
        check_arithmetic::<Fixed16>(FIXED16_TOLERANCE);
    }
    #[cfg(feature = "micromath")]
    check_arithmetic::<F32Micro>(MICROMATH_TOLERANCE);
    #[cfg(feature = "soft-float")]
    check_arithmetic::<SoftFloat>(SOFT32_TOLERANCE);
}

/// The trait's edge cases that every type must get right.
fn check_edge_cases<N: Number>() {
    assert_eq!(N::ONE.checked_div(N::ZERO), None, "{}", N::NAME);
    assert_eq!(N::ZERO.checked_div(N::ZERO), None, "{}", N::NAME);
    assert_eq!(N::MAX.checked_div(N::ZERO), None, "{}", N::NAME);
    // A huge quotient saturates (floats: to MAX, fixed: to MAX).
    let tiny = N::from_f64(1e-9).max(N::from_f64(f64::MIN_POSITIVE));
    let tiny = if tiny == N::ZERO { N::from_f64(1e-4) } else { tiny };
    let huge = N::from_f64(1e4).checked_div(tiny).unwrap();
    assert!(huge.to_f64() >= N::from_f64(1e4).to_f64(), "{}: {huge:?}", N::NAME);
    assert!(N::MAX.checked_div(-tiny).unwrap() <= -N::MAX, "{}", N::NAME);
    // Square roots of negatives and zero are zero.
    assert_eq!(N::from_f64(-4.0).sqrt(), N::ZERO, "{}", N::NAME);
    assert_eq!((-N::MAX).sqrt(), N::ZERO, "{}", N::NAME);
    assert_eq!(N::ZERO.sqrt(), N::ZERO, "{}", N::NAME);
    assert!(N::MAX.sqrt() > N::ONE, "{}", N::NAME);
    // Specular powers: tiny results, never a panic, and 1ⁿ = 1, 0⁰ = 1.
    assert!(N::from_f64(0.99).powi(100_000).to_f64().abs() < 1e-9, "{}", N::NAME);
    assert!(N::from_f64(0.999_99).powi(100_000).to_f64() < 0.5, "{}", N::NAME);
    assert_eq!(N::ONE.powi(100_000), N::ONE, "{}", N::NAME);
    assert_eq!(N::ZERO.powi(0), N::ONE, "{}", N::NAME);
    assert_eq!(N::from_f64(-1.0).powi(3), -N::ONE, "{}", N::NAME);
    // Floors.
    assert_eq!(N::from_f64(-0.5).floor_to_i32(), -1, "{}", N::NAME);
    assert_eq!(N::from_f64(14.9).floor_to_i32(), 14, "{}", N::NAME);
    assert_eq!(N::from_i32(-7).floor_to_i32(), -7, "{}", N::NAME);
    assert_eq!(N::from_f64(f64::NAN), N::ZERO, "{}", N::NAME);
    assert!(N::can_represent(1460.5), "{}", N::NAME);
    assert!(!N::can_represent(f64::NAN) && !N::can_represent(f64::INFINITY), "{}", N::NAME);
}

#[test]
fn edge_cases_of_every_type() {
    check_edge_cases::<f64>();
    check_edge_cases::<f32>();
    #[cfg(feature = "fixed-point")]
    {
        check_edge_cases::<Fixed>();
        check_edge_cases::<Fixed16>();
    }
    #[cfg(feature = "micromath")]
    check_edge_cases::<F32Micro>();
    #[cfg(feature = "soft-float")]
    check_edge_cases::<SoftFloat>();
}

/// Fixed point saturates instead of wrapping at the extremes.
#[cfg(feature = "fixed-point")]
fn check_saturation<N: Number>(big: f64) {
    let two = N::from_i32(2);
    let min = -N::MAX - N::ONE; // the most negative value (−MAX − 1 LSB in two's complement)
    assert_eq!(N::MAX + N::MAX, N::MAX, "{}", N::NAME);
    assert_eq!(N::MAX * two, N::MAX, "{}", N::NAME);
    assert_eq!(N::MAX * (-two), min, "{}", N::NAME);
    assert_eq!(min * two, min, "{}", N::NAME);
    assert_eq!(min * (-two), N::MAX, "{}", N::NAME);
    assert_eq!(min - N::ONE, min, "{}", N::NAME);
    assert_eq!(-min, N::MAX, "{}", N::NAME);
    assert_eq!(min.abs(), N::MAX, "{}", N::NAME);
    assert_eq!(min * min, N::MAX, "{}", N::NAME);
    assert_eq!(N::MAX * N::MAX, N::MAX, "{}", N::NAME);
    let b = N::from_f64(big);
    assert_eq!(b * b, N::MAX, "{}", N::NAME);
    assert_eq!(b * (-b), min, "{}", N::NAME);
    assert_eq!(N::from_f64(1e300), N::MAX, "{}", N::NAME);
    assert_eq!(N::from_f64(-1e300), min, "{}", N::NAME);
    assert_eq!(N::from_i32(i32::MAX).floor_to_i32(), N::MAX.floor_to_i32(), "{}", N::NAME);
    assert_eq!(N::MAX.checked_div(N::from_f64(0.5)), Some(N::MAX), "{}", N::NAME);
    assert_eq!(min.checked_div(N::from_f64(0.5)), Some(min), "{}", N::NAME);
    assert_eq!(min.checked_div(-N::ONE), Some(N::MAX), "{}", N::NAME);
    assert_eq!(N::MAX.powi(3), N::MAX, "{}", N::NAME);
    assert_eq!(N::from_i32(2).powi(1000), N::MAX, "{}", N::NAME);
    assert_eq!(N::dot3([N::MAX; 3], [N::MAX; 3]), N::MAX, "{}", N::NAME);
    assert_eq!(N::dot3([N::MAX; 3], [min; 3]), min, "{}", N::NAME);
    assert_eq!(N::length3([min, N::MAX, min]), N::MAX, "{}", N::NAME);
    // Near the top the exact result still comes out.
    let almost = N::from_f64(N::MAX.to_f64() / 2.0 - 1.0);
    assert!(within((almost * two).to_f64(), almost.to_f64() * 2.0, 0.0, 1e-12), "{}", N::NAME);
}

#[cfg(feature = "fixed-point")]
#[test]
fn fixed_point_saturates_instead_of_wrapping() {
    check_saturation::<Fixed>(1e5);
    check_saturation::<Fixed16>(1e3);
    assert!(Fixed::can_represent(20_000.0) && !Fixed::can_represent(30_000.0));
    assert!(Fixed16::can_represent(2_000.0) && !Fixed16::can_represent(20_000.0));
}

/// dot3 and length3 of vectors with components up to ±20 000 are right, or saturate with the
/// right sign when the exact result is outside the type's range.
fn check_big_vectors<N: Number>(relative: f64) {
    let max = N::MAX.to_f64();
    let mut rng = Rng(12345);
    for i in 0..50_000 {
        let limit = if i % 2 == 0 { 20_000.0 } else { 300.0 };
        let v: [f64; 3] = core::array::from_fn(|_| rng.range(-limit, limit));
        let w: [f64; 3] = core::array::from_fn(|_| rng.range(-1.0, 1.0) * if i % 3 == 0 { limit } else { 1.0 });
        let (a, b) = (v.map(n::<N>), w.map(n::<N>));
        let (x, y) = (a.map(|c| c.to_f64()), b.map(|c| c.to_f64()));
        let length = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
        let got = N::length3(a).to_f64();
        if length >= max {
            assert!(got >= max, "{} length3 {x:?}: {got}", N::NAME);
        } else {
            assert!(within(got, length, 1e-3, relative), "{} length3 {x:?}: {got} vs {length}", N::NAME);
        }
        let dot = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        let got = N::dot3(a, b).to_f64();
        if dot.abs() >= max {
            assert!(got.abs() >= max && got.signum() == dot.signum(), "{} dot3 {x:?}·{y:?}: {got}", N::NAME);
        } else {
            // Each product rounds separately in the default dot3.
            let scale = x.iter().zip(y).map(|(p, q)| (p * q).abs()).sum::<f64>();
            assert!(within(got, dot, 2e-3, relative * 3.0 * scale / dot.abs().max(1e-300)), "{} dot3 {x:?}·{y:?}: {got} vs {dot}", N::NAME);
        }
    }
}

#[test]
fn big_vectors_do_not_overflow_wrongly() {
    check_big_vectors::<f64>(1e-15);
    check_big_vectors::<f32>(2e-7);
    #[cfg(feature = "fixed-point")]
    {
        check_big_vectors::<Fixed>(1e-9);
        check_big_vectors::<Fixed16>(1e-9);
    }
    #[cfg(feature = "micromath")]
    check_big_vectors::<F32Micro>(0.062);
    #[cfg(feature = "soft-float")]
    check_big_vectors::<SoftFloat>(1.5e-8);
}

// ---------------------------------------------------------------------------------------------
// Ray–sphere mini-benchmark
// ---------------------------------------------------------------------------------------------

/// The stable sphere test as the tracer does it, with trait operations only: a world ray from
/// `eye` toward `target` (normalised in `N`, as the camera does), taken into the sphere's object
/// space by the inverse transform (scale 1/r, translate −c/r), then the discriminant from the
/// perpendicular vector and the near root `c/q`. Returns the nearest positive `t` (a world
/// distance) of a hit.
fn sphere_hit<N: Number>(eye: [f64; 3], target: [f64; 3], centre: [f64; 3], radius: f64) -> Option<f64> {
    let e = eye.map(n::<N>);
    let offset: [N; 3] = core::array::from_fn(|i| n::<N>(target[i]) - e[i]);
    let reciprocal = N::ONE.checked_div(N::length3(offset))?;
    let direction = offset.map(|c| c * reciprocal);
    let scale = n::<N>(1.0 / radius);
    let origin: [N; 3] = core::array::from_fn(|i| e[i] * scale + n::<N>(-centre[i] / radius));
    let d = direction.map(|c| c * scale);
    let a = N::dot3(d, d);
    let b = N::dot3(origin, d);
    let along = b.checked_div(a)?;
    let perpendicular: [N; 3] = core::array::from_fn(|i| origin[i] - d[i] * along);
    let discriminant = a * (N::ONE - N::dot3(perpendicular, perpendicular));
    if discriminant < N::ZERO {
        return None;
    }
    let c = N::dot3(origin, origin) - N::ONE;
    let root = discriminant.sqrt();
    let q = if b < N::ZERO { -b + root } else { -b - root };
    [c.checked_div(q), q.checked_div(a)].into_iter().flatten().filter(|t| *t > N::ZERO).map(|t| t.to_f64()).reduce(f64::min)
}

struct SphereCase {
    name: &'static str,
    eye: [f64; 3],
    centre: [f64; 3],
    radius: f64,
}

/// The fraction of rays whose hit/miss differs from f64, and the worst relative error of the
/// hit point's distance from the centre, over `rays` rays aimed uniformly at a disc of 1.05 r
/// around the centre, perpendicular to the line of sight.
fn sphere_flips<N: Number>(case: &SphereCase, rays: u32) -> (f64, f64) {
    let mut rng = Rng(0xD1B5_4A32_D192_ED03);
    let axis: [f64; 3] = core::array::from_fn(|i| case.centre[i] - case.eye[i]);
    let length = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let w = axis.map(|c| c / length);
    // Two unit vectors perpendicular to w.
    let helper = if w[0].abs() < 0.9 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
    let cross = |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let u0 = cross(w, helper);
    let ul = (u0[0] * u0[0] + u0[1] * u0[1] + u0[2] * u0[2]).sqrt();
    let u = u0.map(|c| c / ul);
    let v = cross(w, u);
    let (mut flips, mut worst_surface) = (0u32, 0.0f64);
    for _ in 0..rays {
        let (radius, angle) = (1.05 * case.radius * rng.unit().sqrt(), core::f64::consts::TAU * rng.unit());
        let (s, t) = (radius * angle.cos(), radius * angle.sin());
        let target: [f64; 3] = core::array::from_fn(|i| case.centre[i] + s * u[i] + t * v[i]);
        let reference = sphere_hit::<f64>(case.eye, target, case.centre, case.radius);
        let got = sphere_hit::<N>(case.eye, target, case.centre, case.radius);
        match (reference, got) {
            (Some(_), Some(t)) => {
                // Where the N ray's t puts the hit on the exact ray.
                let offset: [f64; 3] = core::array::from_fn(|i| target[i] - case.eye[i]);
                let l = (offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2]).sqrt();
                let p: [f64; 3] = core::array::from_fn(|i| case.eye[i] + offset[i] / l * t - case.centre[i]);
                let distance = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
                worst_surface = worst_surface.max((distance - case.radius).abs() / case.radius);
            }
            (None, None) => {}
            _ => flips += 1,
        }
    }
    (f64::from(flips) / f64::from(rays), worst_surface)
}

fn sphere_cases() -> [SphereCase; 6] {
    [
        SphereCase { name: "snooker r=26.25 D~1400", eye: [0.0, 220.0, 1380.0], centre: [0.0, 26.25, 0.0], radius: 26.25 },
        SphereCase { name: "snooker far ball D~2430", eye: [0.0, 220.0, 1380.0], centre: [-292.0, 26.25, -1047.5], radius: 26.25 },
        SphereCase { name: "r=1 D=10", eye: [3.0, 4.0, 12.0], centre: [3.0, 4.0, 2.0], radius: 1.0 },
        SphereCase { name: "r=1 D=100", eye: [0.0, 0.0, 100.0], centre: [0.0, 0.0, 0.0], radius: 1.0 },
        SphereCase { name: "r=1 D=1000", eye: [600.0, 0.0, 800.0], centre: [0.0, 0.0, 0.0], radius: 1.0 },
        SphereCase { name: "r=1 D=10000", eye: [0.0, 6000.0, 8000.0], centre: [0.0, 0.0, 0.0], radius: 1.0 },
    ]
}

const SPHERE_RAYS: u32 = 200_000;

fn sphere_row<N: Number>() -> Vec<(f64, f64)> {
    let row: Vec<(f64, f64)> = sphere_cases().iter().map(|case| sphere_flips::<N>(case, SPHERE_RAYS)).collect();
    let cells: Vec<String> = row.iter().map(|(flips, surface)| format!("{:>8.4}% {:>8.1e}", 100.0 * flips, surface)).collect();
    println!("{:>14} | {}", N::NAME, cells.join(" | "));
    row
}

#[test]
fn ray_sphere_accuracy_benchmark() {
    let names: Vec<String> = sphere_cases().iter().map(|case| format!("{:>19}", case.name)).collect();
    println!("hit/miss flips against f64 and worst |‖P−c‖−r|/r, {SPHERE_RAYS} rays each");
    println!("{:>14} | {}", "type", names.join(" | "));
    sphere_row::<f64>();
    let f32_row = sphere_row::<f32>();
    assert!(f32_row[0].0 < 1e-4);
    #[cfg(feature = "fixed-point")]
    {
        let fixed = sphere_row::<Fixed>();
        assert!(fixed[0].0 < 1e-4, "fixed: {:.4}% flips on the snooker case", 100.0 * fixed[0].0);
        assert!(fixed.iter().all(|(flips, _)| *flips < 1e-4), "fixed: {fixed:?}");
        sphere_row::<Fixed16>();
    }
    #[cfg(feature = "micromath")]
    sphere_row::<F32Micro>();
    #[cfg(feature = "soft-float")]
    {
        let soft = sphere_row::<SoftFloat>();
        assert!(soft.iter().all(|(flips, _)| *flips < 1e-4), "soft32: {soft:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Whole thesis scenes against f64
// ---------------------------------------------------------------------------------------------

use microtrace::pixel::FrameBuffer;
use microtrace::render::{Pga, Statistics, Whole};
use microtrace::model::SceneDescription;
use microtrace::scene::Scene;

const MAX_OBJECTS: usize = 512;

const SCENES: [(&str, &[u8]); 2] =
    [("snooker", include_bytes!("../../scenes/snooker.mts")), ("lattice", include_bytes!("../../scenes/lattice.mts"))];

fn description(text: &[u8]) -> Box<SceneDescription<MAX_OBJECTS>> {
    Box::new(microtrace::parser::parse::<MAX_OBJECTS>(text).unwrap())
}

fn render<N: Number>(description: &SceneDescription<MAX_OBJECTS>) -> Vec<u8> {
    let scene = Scene::<N, MAX_OBJECTS>::prepare(description).unwrap();
    let (width, height) = (scene.viewport().width(), scene.viewport().height());
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let mut frame = FrameBuffer::new(&mut pixels, width, height).unwrap();
    microtrace::render::render(&scene, Pga, Whole, &mut frame, &mut Statistics::default());
    pixels
}

/// How an image differs from the reference: identical pixels, pixels one shade step away in the
/// same colour group, and worse ones (a different group, i.e. a different object or the
/// background, or more than one step).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Comparison {
    pixels: usize,
    identical: usize,
    one_step: usize,
    worse: usize,
    max_shade_difference: u8,
}

impl Comparison {
    fn of(reference: &[u8], image: &[u8]) -> Self {
        let mut comparison = Self { pixels: reference.len(), identical: 0, one_step: 0, worse: 0, max_shade_difference: 0 };
        for (&a, &b) in reference.iter().zip(image) {
            if a == b {
                comparison.identical += 1;
            } else if a / 16 == b / 16 && (a % 16).abs_diff(b % 16) == 1 {
                comparison.one_step += 1;
                comparison.max_shade_difference = comparison.max_shade_difference.max(1);
            } else {
                comparison.worse += 1;
                let difference = if a / 16 == b / 16 { (a % 16).abs_diff(b % 16) } else { 16 };
                comparison.max_shade_difference = comparison.max_shade_difference.max(difference);
            }
        }
        comparison
    }

    fn identical_fraction(&self) -> f64 {
        self.identical as f64 / self.pixels as f64
    }
}

fn compare<N: Number>(name: &str, description: &SceneDescription<MAX_OBJECTS>, reference: &[u8]) -> Comparison {
    let start = std::time::Instant::now();
    let comparison = Comparison::of(reference, &render::<N>(description));
    println!(
        "{name:>8} {:>4}x{:<4} {:>14}: {:>8.4}% identical, {:>6} one step, {:>5} worse (max shade difference {:>2}; 16 = other group) [{:.2?} on the host]",
        description.viewport.width(),
        description.viewport.height(),
        N::NAME,
        100.0 * comparison.identical_fraction(),
        comparison.one_step,
        comparison.worse,
        comparison.max_shade_difference,
        start.elapsed()
    );
    comparison
}

fn compare_scenes(width: u16, height: u16) {
    for (name, text) in SCENES {
        let mut description = description(text);
        if (width, height) != (0, 0) {
            description.fit_to_size(width, height);
        }
        let reference = render::<f64>(&description);
        let objects = reference.iter().filter(|&&index| index != description.background).count();
        println!("{name:>8}: f64 reference, {:.1}% of the pixels show an object", 100.0 * objects as f64 / reference.len() as f64);
        assert!(objects > reference.len() / 20, "{name}: the reference is nearly empty");
        compare::<f32>(name, &description, &reference);
        #[cfg(feature = "fixed-point")]
        {
            let fixed = compare::<Fixed>(name, &description, &reference);
            assert!(fixed.identical_fraction() >= 0.995, "{name}: {fixed:?}");
            assert_eq!(fixed.worse, 0, "{name}: {fixed:?}");
            compare::<Fixed16>(name, &description, &reference);
        }
        #[cfg(feature = "micromath")]
        compare::<F32Micro>(name, &description, &reference);
        #[cfg(feature = "soft-float")]
        {
            let soft = compare::<SoftFloat>(name, &description, &reference);
            assert!(soft.identical_fraction() >= 0.9995, "{name}: {soft:?}");
        }
    }
}

/// The thesis scenes at the OLED's 128x64 in every type against f64.
#[test]
fn thesis_scenes_at_128x64_match_f64() {
    compare_scenes(128, 64);
}

/// The thesis scenes at their own sizes (528x480 and 466x480).
#[test]
fn thesis_scenes_at_full_size_match_f64() {
    compare_scenes(0, 0);
}

/// `Fixed`'s chunked long division against an exact 128-bit reference, over raw values of every
/// magnitude.
#[cfg(feature = "fixed-point")]
#[test]
fn fixed_division_is_exactly_rounded() {
    let mut rng = Rng(0x1234_5678_9ABC_DEF1);
    let special = [0, 1, -1, 2, i64::MAX, i64::MIN, i64::MIN + 1, 1 << 32, -(1 << 32), (1 << 32) - 1, 1 << 31, 1 << 63 >> 1, 0xFFFF_FFFF_0000_0000u64 as i64 >> 1];
    for i in 0..1_000_000 {
        let mut a = (rng.next_u64() as i64) >> (rng.next_u64() % 64);
        let mut b = (rng.next_u64() as i64) >> (rng.next_u64() % 64);
        if i % 7 == 0 {
            a = special[(rng.next_u64() % special.len() as u64) as usize];
        }
        if i % 5 == 0 {
            // Powers of two and their neighbours: the normalisation boundaries.
            b = ((1u64 << (rng.next_u64() % 63)) as i64).wrapping_add((rng.next_u64() % 3) as i64 - 1);
            if i % 2 == 0 {
                b = -b;
            }
        }
        let got = Fixed::from_bits(a).checked_div(Fixed::from_bits(b)).map(Fixed::to_bits);
        if b == 0 {
            assert_eq!(got, None);
            continue;
        }
        let (n, d) = (i128::from(a) << 32, i128::from(b));
        let (q, r) = (n / d, n % d);
        // Round half away from zero.
        let q = if 2 * r.abs() >= d.abs() { q + if (n < 0) != (d < 0) { -1 } else { 1 } } else { q };
        let expected = q.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64;
        assert_eq!(got, Some(expected), "{a} / {b}");
    }
}

/// `Fixed`'s multiplication against an exact 128-bit reference.
#[cfg(feature = "fixed-point")]
#[test]
fn fixed_multiplication_is_exactly_rounded() {
    let mut rng = Rng(0x0F1E_2D3C_4B5A_6978);
    for _ in 0..200_000 {
        let a = (rng.next_u64() as i64) >> (rng.next_u64() % 64);
        let b = (rng.next_u64() as i64) >> (rng.next_u64() % 64);
        let got = (Fixed::from_bits(a) * Fixed::from_bits(b)).to_bits();
        let p = i128::from(a) * i128::from(b);
        // Round to nearest, ties toward +∞.
        let q = (p + (1 << 31)) >> 32;
        let expected = q.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64;
        assert_eq!(got, expected, "{a} * {b}");
    }
}

/// `Fixed::dot3` (one rounding of the exact sum) against an exact 128-bit reference, on both of
/// its paths (components below 2²⁷ and beyond).
#[cfg(feature = "fixed-point")]
#[test]
fn fixed_dot3_is_exactly_rounded() {
    let mut rng = Rng(0x5555_AAAA_1234_4321);
    for i in 0..300_000 {
        let largest = if i % 3 == 0 { 64 } else { 60 };
        let mut raw = || (rng.next_u64() as i64) >> (64 - largest + (rng.next_u64() % largest as u64) as u32).min(63);
        let a: [i64; 3] = core::array::from_fn(|_| raw());
        let b: [i64; 3] = core::array::from_fn(|_| raw());
        let got = Fixed::dot3(a.map(Fixed::from_bits), b.map(Fixed::from_bits)).to_bits();
        let sum: i128 = (0..3).map(|k| i128::from(a[k]) * i128::from(b[k])).fold(0i128, |s, p| s.saturating_add(p));
        let expected = (sum.saturating_add(1 << 31) >> 32).clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64;
        assert_eq!(got, expected, "{a:?} · {b:?}");
    }
}
