extern crate std;
use std::vec::Vec;

use super::*;
use crate::geometry::{Ray, Vector3};

fn ray(origin: [f64; 3], direction: [f64; 3]) -> Ray<f64> {
    Ray { origin: Vector3::from_f64(origin), direction: Vector3::from_f64(direction) }
}

fn hit(primitive: Primitive, r: Ray<f64>) -> Option<(f64, [f64; 3])> {
    primitive.intersect(&r, Interval::unbounded()).map(|h| (h.t, h.normal.to_f64()))
}

#[test]
fn sphere_front_hit_and_hit_from_inside() {
    assert_eq!(hit(Primitive::Sphere, ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0])), Some((4.0, [0.0, 0.0, 1.0])));
    // From the centre the ray sees the far side (the thesis's single root missed it).
    assert_eq!(hit(Primitive::Sphere, ray([0.0, 0.0, 0.0], [0.0, 0.0, -2.0])), Some((0.5, [0.0, 0.0, -1.0])));
    assert_eq!(hit(Primitive::Sphere, ray([0.0, 2.0, 5.0], [0.0, 0.0, -1.0])), None);
    // Behind the origin: no hit.
    assert_eq!(hit(Primitive::Sphere, ray([0.0, 0.0, 5.0], [0.0, 0.0, 1.0])), None);
}

#[test]
fn sphere_respects_the_interval() {
    let r = ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0]);
    assert!(Primitive::Sphere.intersect(&r, Interval::below(4.0)).is_none());
    assert!(Primitive::Sphere.intersect(&r, Interval { max: 4.0, include_max: true }).is_some());
    assert!(Primitive::Sphere.occluded(&r, Interval::below(4.5)));
    assert!(!Primitive::Sphere.occluded(&r, Interval::below(3.5)));
}

#[test]
fn cylinder_caps_side_and_axis_parallel_ray() {
    assert_eq!(hit(Primitive::Cylinder, ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0])), Some((4.0, [0.0, 0.0, 1.0])));
    assert_eq!(hit(Primitive::Cylinder, ray([0.5, 0.0, -3.0], [0.0, 0.0, 1.0])), Some((3.0, [0.0, 0.0, -1.0])));
    assert_eq!(hit(Primitive::Cylinder, ray([5.0, 0.0, 0.5], [-1.0, 0.0, 0.0])), Some((4.0, [1.0, 0.0, 0.0])));
    // Beyond the ends of the side.
    assert_eq!(hit(Primitive::Cylinder, ray([5.0, 0.0, 1.5], [-1.0, 0.0, 0.0])), None);
    // Parallel to the axis outside the radius.
    assert_eq!(hit(Primitive::Cylinder, ray([2.0, 0.0, 5.0], [0.0, 0.0, -1.0])), None);
}

#[test]
fn cone_side_normal_is_the_gradient_and_base_is_capped() {
    // Horizontal ray at z = 0.5 hits the side at x = 0.5; gradient (0.5, 0, -0.5).
    assert_eq!(hit(Primitive::Cone, ray([5.0, 0.0, 0.5], [-1.0, 0.0, 0.0])), Some((4.5, [0.5, 0.0, -0.5])));
    assert_eq!(hit(Primitive::Cone, ray([0.2, 0.0, 5.0], [0.0, 0.0, -1.0])), Some((4.0, [0.0, 0.0, 1.0])));
    // Below the apex: the lower nappe of x² + y² = z² is not part of the cone.
    assert_eq!(hit(Primitive::Cone, ray([5.0, 0.0, -0.5], [-1.0, 0.0, 0.0])), None);
}

#[test]
fn cone_apex_and_rays_parallel_to_the_side() {
    // Along the axis from below: meets the apex.
    let (t, normal) = hit(Primitive::Cone, ray([0.0, 0.0, -1.0], [0.0, 0.0, 1.0])).unwrap();
    assert_eq!((t, normal), (1.0, [0.0, 0.0, -1.0]));
    // Parallel to a generator line (A = 0), from outside: meets the far side once.
    let (t, _) = hit(Primitive::Cone, ray([-2.0, 0.0, 0.0], [1.0, 0.0, 1.0])).unwrap();
    assert!((t - 1.0).abs() < 1e-12, "{t}");
    // Lying on the surface through the apex: only the base rim.
    let (t, normal) = hit(Primitive::Cone, ray([1.0, 0.0, -1.0], [-1.0, 0.0, 1.0])).unwrap();
    assert_eq!((t, normal), (2.0, [0.0, 0.0, 1.0]));
}

#[test]
fn cube_faces_edges_and_corners() {
    assert_eq!(hit(Primitive::Cube, ray([0.5, 0.5, 5.0], [0.0, 0.0, -1.0])), Some((4.0, [0.0, 0.0, 1.0])));
    assert_eq!(hit(Primitive::Cube, ray([-3.0, 0.5, 0.5], [1.0, 0.0, 0.0])), Some((3.0, [-1.0, 0.0, 0.0])));
    // Exactly along an edge: bounds are inclusive.
    assert_eq!(hit(Primitive::Cube, ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0])), Some((4.0, [0.0, 0.0, 1.0])));
    // Just outside the edge.
    assert_eq!(hit(Primitive::Cube, ray([-1e-9, 0.0, 5.0], [0.0, 0.0, -1.0])), None);
    // Through two opposite corners.
    let (t, _) = hit(Primitive::Cube, ray([-1.0, -1.0, -1.0], [1.0, 1.0, 1.0])).unwrap();
    assert_eq!(t, 1.0);
    // From inside: the exit face.
    assert_eq!(hit(Primitive::Cube, ray([0.5, 0.5, 0.5], [0.0, 2.0, 0.0])), Some((0.25, [0.0, 1.0, 0.0])));
    // Zero direction never divides and never hits.
    assert_eq!(hit(Primitive::Cube, ray([0.5, 0.5, 0.5], [0.0, 0.0, 0.0])), None);
}

#[test]
fn zero_direction_misses_every_primitive() {
    for primitive in Primitive::ALL {
        assert_eq!(hit(primitive, ray([0.2, 0.1, 0.5], [0.0, 0.0, 0.0])), None, "{primitive:?}");
    }
}

#[test]
fn grazing_sphere_ray_is_a_single_tangent_hit() {
    let tangent = hit(Primitive::Sphere, ray([1.0, 0.0, 5.0], [0.0, 0.0, -1.0]));
    assert_eq!(tangent.map(|h| h.0), Some(5.0));
    assert_eq!(hit(Primitive::Sphere, ray([1.0 + 1e-12, 0.0, 5.0], [0.0, 0.0, -1.0])), None);
}

/// Object-space directions of large objects are tiny (one over the size); scaled to unit size
/// first, Q32.32 finds the same hits as f64 (a cone 7000 across missed by hundreds of units
/// before), and float results are bit-identical to the unscaled computation.
#[cfg(feature = "fixed-point")]
#[test]
fn large_objects_keep_their_precision_in_fixed_point() {
    use crate::number::{Fixed, Number};
    let scale = 1.0 / 7000.0;
    let origin = [0.2, 0.7, 0.6];
    for primitive in Primitive::ALL {
        for k in 0..50 {
            let x = -1.0 + 0.04 * f64::from(k);
            let direction = [x * scale, -scale, 0.3 * scale];
            let reference = primitive.intersect(&ray(origin, direction), Interval::unbounded());
            let fixed_ray = Ray { origin: Vector3::<Fixed>::from_f64(origin), direction: Vector3::from_f64(direction) };
            let fixed = primitive.intersect(&fixed_ray, Interval::unbounded());
            assert_eq!(reference.is_some(), fixed.is_some(), "{primitive:?} {x}");
            if let (Some(a), Some(b)) = (reference, fixed) {
                // The direction itself converts with ~2·10⁻⁶ relative error (2⁻³² on 1.4·10⁻⁴).
                assert!((a.t - b.t.to_f64()).abs() < 1e-5 * a.t, "{primitive:?} {x}: {} {}", a.t, b.t.to_f64());
            }
        }
    }
}

#[test]
fn direction_scaling_is_exact_in_floating_point() {
    // t scales exactly with the direction: a ray with a direction 2^-20 as long hits at 2^20 t.
    let short = hit(Primitive::Sphere, ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0 / 1048576.0])).unwrap();
    assert_eq!(short, (4.0 * 1048576.0, [0.0, 0.0, 1.0]));
    let cone = hit(Primitive::Cone, ray([5.0, 0.0, 0.5], [-3.0, 0.0, 0.0])).unwrap();
    assert_eq!(cone, (1.5, [0.5, 0.0, -0.5]));
}

/// A cone 10⁻⁴ thick (scenes/hard/near_singular.mts) seen from 2 units: its discriminant from
/// the cross product agrees with f64's in f32, where b² − a c lost 1 % of the pixels.
#[test]
fn thin_cone_discriminant_is_stable_in_f32() {
    use crate::geometry::Matrix4;
    let mut forward = Matrix4::IDENTITY;
    forward.scale([0.0001, 0.5, 0.5]);
    forward.rotate(1, 20.0);
    forward.translate([0.4, -0.8, -0.6]);
    let inverse = forward.affine_inverse().unwrap();
    let eye = inverse.transform_point([0.0, 0.0, 2.0]);
    let (mut hits, mut disagreements) = (0, 0);
    for row in 0..64 {
        for column in 0..64 {
            let target = [0.3 + 0.005 * f64::from(column), -1.0 + 0.005 * f64::from(row), 0.0];
            let target = inverse.transform_point(target);
            let direction = [0, 1, 2].map(|k| target[k] - eye[k]);
            let exact = hit(Primitive::Cone, ray(eye, direction)).is_some();
            let single = Ray { origin: Vector3::<f32>::from_f64(eye), direction: Vector3::from_f64(direction) };
            let found = Primitive::Cone.intersect(&single, Interval::unbounded()).is_some();
            hits += usize::from(exact);
            disagreements += usize::from(exact != found);
        }
    }
    assert!(hits > 200, "{hits}");
    assert!(disagreements <= 2, "{disagreements} of {hits} hits");
}

/// `crossings` (what CSG's spans are made of) agrees with `intersect`: the first crossing in
/// front of the origin is the hit, with the same normal, for every primitive and many rays; a
/// closed surface is crossed an even number of times by a ray that is not tangent, and a ray
/// from inside crosses it an odd number of times in front.
#[test]
fn crossings_agree_with_intersect() {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut random = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for primitive in Primitive::ALL {
        let mut hits = 0;
        for _ in 0..400 {
            // From anywhere near, aimed at a point near the primitives' common part.
            let origin = [3.0 * random(), 3.0 * random(), 3.0 * random()];
            let target = [0.5 + 0.7 * random(), 0.5 * random(), 0.5 + 0.6 * random()];
            let direction = [target[0] - origin[0], target[1] - origin[1], target[2] - origin[2]];
            let r = ray(origin, direction);
            let crossings = primitive.crossings(&r);
            let list: Vec<(f64, [f64; 3])> = crossings.iter().map(|(t, n)| (*t, n.to_f64())).collect();
            assert!(list.windows(2).all(|pair| pair[0].0 <= pair[1].0), "{primitive:?}: not in order: {list:?}");
            let first_in_front = list.iter().copied().find(|(t, _)| *t > 0.0);
            let expected = hit(primitive, r);
            if let Primitive::Torus(_) = primitive {
                // The torus's quartic is expanded about the box's entry here (which may be behind
                // the origin) and about the origin in `intersect`: the roots agree to rounding.
                match (first_in_front, expected) {
                    (Some((t, n)), Some((u, m))) => {
                        assert!((t - u).abs() <= 1e-12 * u.max(1.0), "{primitive:?}: {t} against {u}");
                        assert!(n.iter().zip(m).all(|(a, b)| (a - b).abs() <= 1e-9), "{primitive:?}: {n:?} against {m:?}");
                    }
                    (a, b) => assert_eq!(a.is_some(), b.is_some(), "{primitive:?} from {origin:?} along {direction:?}"),
                }
            } else {
                assert_eq!(first_in_front, expected, "{primitive:?} from {origin:?} along {direction:?}");
            }
            hits += usize::from(first_in_front.is_some());
            assert!(list.len().is_multiple_of(2) || list.len() == 1, "{primitive:?}: {} crossings: {list:?}", list.len());
        }
        assert!(hits > 40, "{primitive:?}: only {hits} of 400 rays hit");
    }
}

/// A random stream in [-1, 1) for the property tests below.
fn random_stream(mut state: u64) -> impl FnMut() -> f64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

#[test]
fn frustum_side_outside_and_inside() {
    let half = Primitive::Frustum(crate::model::Taper::HALF);
    // At z = 0.5 the radius is 0.75: met from outside at x = 0.75, gradient (0.75, 0, -0.375).
    assert_eq!(hit(half, ray([5.0, 0.0, 0.5], [-1.0, 0.0, 0.0])), Some((4.25, [0.75, 0.0, -0.375])));
    // From the axis the inside is met (no caps), the normal still the outward gradient.
    assert_eq!(hit(half, ray([0.0, 0.0, 0.5], [1.0, 0.0, 0.0])), Some((0.75, [0.75, 0.0, -0.375])));
    // Along the axis: through both open ends.
    assert_eq!(hit(half, ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0])), None);
    // Beyond either end of the side.
    assert_eq!(hit(half, ray([5.0, 0.0, 1.5], [-1.0, 0.0, 0.0])), None);
    assert_eq!(hit(half, ray([5.0, 0.0, -0.5], [-1.0, 0.0, 0.0])), None);
}

/// Tapers 1 and 0 are the side of the closed cylinder and cone: wherever those are met on the
/// side (not a cap), the frustum gives the same hit, and it is never met where they are not.
#[test]
fn frustum_of_taper_one_and_zero_is_the_cylinder_and_cone_side() {
    let mut random = random_stream(0x5DEE_CE66_D1CE_B00C);
    for (taper, closed) in [(crate::model::Taper::CYLINDER, Primitive::Cylinder), (crate::model::Taper::from_steps(0), Primitive::Cone)] {
        let frustum = Primitive::Frustum(taper);
        let mut sides = 0;
        for _ in 0..2000 {
            let origin = [3.0 * random(), 3.0 * random(), 0.5 + 3.0 * random()];
            let target = [0.8 * random(), 0.8 * random(), 0.5 + 0.5 * random()];
            let r = ray(origin, [0, 1, 2].map(|k| target[k] - origin[k]));
            let open = hit(frustum, r);
            match hit(closed, r) {
                Some((t, normal)) if normal[0] != 0.0 || normal[1] != 0.0 => {
                    let (u, m) = open.unwrap_or_else(|| panic!("{closed:?} side met at {t} from {origin:?}, the frustum missed"));
                    assert!((t - u).abs() <= 1e-12 * t.max(1.0), "{closed:?}: {t} against {u}");
                    assert!(normal.iter().zip(m).all(|(a, b)| (a - b).abs() <= 1e-12), "{normal:?} against {m:?}");
                    sides += 1;
                }
                // Through a cap: the open frustum may meet the side beyond it, never before.
                Some((t, _)) => assert!(open.is_none_or(|(u, _)| u >= t), "{closed:?} cap at {t}, frustum at {open:?}"),
                None => assert_eq!(open, None, "{closed:?} missed from {origin:?}"),
            }
        }
        assert!(sides > 300, "{closed:?}: {sides} side hits");
    }
}

/// The triangle against an independent test, Möller–Trumbore in world space: random triangles
/// (any orientation, thin ones too), their transform built as NFF's polygons build it, random
/// rays aimed near them; the hit or miss agrees except within rounding of an edge, and where
/// both hit, at the same place.
#[test]
fn triangle_agrees_with_moller_trumbore() {
    use crate::geometry::{AffineTransform, Matrix4};
    let mut random = random_stream(0x2545_F491_4F6C_DD1D);
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let cross = |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let (mut hits, mut near_edges) = (0, 0);
    for case in 0..3000 {
        let spread = if case % 3 == 0 { 0.05 } else { 2.0 };
        let v0 = [random(), random(), random()];
        let v1 = [v0[0] + spread * random(), v0[1] + random(), v0[2] + random()];
        let v2 = [v0[0] + random(), v0[1] + spread * random(), v0[2] + random()];
        let (e1, e2) = (sub(v1, v0), sub(v2, v0));
        let normal = cross(e1, e2);
        let area = dot(normal, normal).sqrt();
        if area < 1e-6 {
            continue;
        }
        let mut world_from_object = Matrix4::IDENTITY;
        for k in 0..3 {
            world_from_object.rows[0][k] = e1[k];
            world_from_object.rows[1][k] = e2[k];
            world_from_object.rows[2][k] = normal[k] / area.sqrt();
            world_from_object.rows[3][k] = v0[k];
        }
        let object_from_world = AffineTransform::<f64>::from_matrix(&world_from_object.affine_inverse().unwrap());
        let origin = [4.0 * random(), 4.0 * random(), 4.0 * random()];
        let (a, b) = (random().abs(), random().abs());
        let target = [0, 1, 2].map(|k| v0[k] + 1.2 * (a * e1[k] + b * e2[k]) - 0.1 * (e1[k] + e2[k]));
        let direction = sub(target, origin);
        // Möller–Trumbore.
        let p = cross(direction, e2);
        let det = dot(e1, p);
        let expected = (det.abs() > 1e-12).then(|| {
            let s = sub(origin, v0);
            let u = dot(s, p) / det;
            let q = cross(s, e1);
            let v = dot(direction, q) / det;
            (dot(e2, q) / det, u, v)
        });
        let world_ray = ray(origin, direction);
        let local = object_from_world.ray(&world_ray);
        let found = hit(Primitive::Triangle, local);
        match expected {
            Some((t, u, v)) if t > 0.0 => {
                let margin = 1e-9;
                let inside = u >= margin && v >= margin && u + v <= 1.0 - margin;
                let outside = u < -margin || v < -margin || u + v > 1.0 + margin;
                if inside {
                    let (found_t, _) = found.unwrap_or_else(|| panic!("case {case}: missed at u {u} v {v}"));
                    assert!((found_t - t).abs() <= 1e-9 * t.max(1.0), "case {case}: t {found_t} against {t}");
                    hits += 1;
                } else if outside {
                    assert_eq!(found, None, "case {case}: hit outside, u {u} v {v}");
                } else {
                    near_edges += 1;
                }
            }
            _ => {}
        }
    }
    assert!(hits > 500, "{hits} hits");
    assert!(near_edges < 10, "{near_edges} within rounding of an edge");
}

/// The disc: the plane z = 0 within radius 1, from both sides, its normal +z; a ray in its
/// plane never meets it, and one just beyond its rim misses.
#[cfg(feature = "disc")]
#[test]
fn disc_hits_from_both_sides_inside_its_rim_only() {
    assert_eq!(hit(Primitive::Disc, ray([0.5, 0.0, 5.0], [0.0, 0.0, -1.0])), Some((5.0, [0.0, 0.0, 1.0])));
    assert_eq!(hit(Primitive::Disc, ray([0.0, -0.5, -2.0], [0.0, 0.0, 2.0])), Some((1.0, [0.0, 0.0, 1.0])));
    // On the rim (x² + y² = 1) counts; just beyond it does not.
    assert!(hit(Primitive::Disc, ray([1.0, 0.0, 1.0], [0.0, 0.0, -1.0])).is_some());
    assert_eq!(hit(Primitive::Disc, ray([1.0 + 1e-9, 0.0, 1.0], [0.0, 0.0, -1.0])), None);
    // In its plane, and behind the origin.
    assert_eq!(hit(Primitive::Disc, ray([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0])), None);
    assert_eq!(hit(Primitive::Disc, ray([0.0, 0.0, 5.0], [0.0, 0.0, 1.0])), None);
    // Oblique, and `occluded` agrees with `intersect` within an interval.
    let oblique = ray([-3.0, 0.0, 3.0], [1.0, 0.0, -1.0]);
    assert_eq!(hit(Primitive::Disc, oblique), Some((3.0, [0.0, 0.0, 1.0])));
    assert!(Primitive::Disc.occluded(&oblique, Interval::below(3.5)));
    assert!(!Primitive::Disc.occluded(&oblique, Interval::below(2.5)));
    assert_eq!(Primitive::Disc.crossings(&oblique).len, 1);
    // Open: no solid's operand.
    assert!(!Primitive::Disc.is_closed());
}
