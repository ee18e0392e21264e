//! The unit triangle (0,0,0), (1,0,0), (0,1,0) in the plane z = 0: its transform maps it onto
//! any triangle of a scene (NFF's polygons, split at preparation, and patches). In its own
//! space the test is a plane and two barycentric coordinates, u ≥ 0, v ≥ 0, u + v ≤ 1.

use super::{Hit, ScaledInterval};
use crate::geometry::{Ray, Vector3};
use crate::model::VertexNormals;
use crate::number::Number;

/// Where the ray crosses the triangle's plane inside it, `t` and the barycentric (u, v) there
/// (the hit point's x and y); a ray in the plane (d.z = 0) never meets it.
#[inline]
fn crossing<N: Number>(ray: &Ray<N>) -> Option<(N, N, N)> {
    let (p, d) = (ray.origin, ray.direction);
    if d.z == N::ZERO {
        return None;
    }
    let t = (-p.z).checked_div(d.z)?;
    let (u, v) = (p.x + d.x * t, p.y + d.y * t);
    (u >= N::ZERO && v >= N::ZERO && u + v <= N::ONE).then_some((t, u, v))
}

/// The crossing with the plane's normal, +z.
#[inline]
fn surface<N: Number>(ray: &Ray<N>) -> Option<(N, Vector3<N>)> {
    crossing(ray).map(|(t, _, _)| (t, Vector3::new(N::ZERO, N::ZERO, N::ONE)))
}

/// A patch: the triangle's hit with the corners' normals interpolated there (NFF's `pp`).
pub fn intersect_patch<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>, normals: VertexNormals) -> Option<Hit<N>> {
    crossing(ray).filter(|(t, _, _)| interval.contains(*t)).map(|(t, u, v)| Hit { t, normal: normals.at(u, v) })
}

/// Where a patch's shadow rays start, as an offset from its hit point (u, v, 0) in object
/// space: the point lifted onto the smooth surface its corner normals describe (Hanika's fix of
/// the shadow terminator, Ray Tracing Gems II, 2021, ch. 4). A flat triangle shaded with
/// interpolated normals turns toward a light its neighbours still hide, and its shadow rays,
/// leaving the flat facet, meet them: dark facets along the terminator (the SPD teapot's
/// belly). Each corner's tangent plane (through the corner, normal to its normal) lifts the
/// point when it lies below the plane, by the corner's barycentric weight; Phong tessellation.
/// Planes map to planes under the object's affine map, so the lifted point lies on the same
/// planes in world space.
pub fn terminator_lift<N: Number>(u: N, v: N, normals: VertexNormals) -> Vector3<N> {
    let point = Vector3::new(u, v, N::ZERO);
    let corners = [Vector3::new(N::ZERO, N::ZERO, N::ZERO), Vector3::new(N::ONE, N::ZERO, N::ZERO), Vector3::new(N::ZERO, N::ONE, N::ZERO)];
    let weights = [N::ONE - u - v, u, v];
    let mut lift = Vector3::new(N::ZERO, N::ZERO, N::ZERO);
    for ((corner, weight), normal) in corners.into_iter().zip(weights).zip(normals.0) {
        let normal = normal.map(|c| N::from_i32(i32::from(c)).times_power_of_two(VertexNormals::STEP_EXPONENT));
        let normal = Vector3::new(normal[0], normal[1], normal[2]);
        let height = (point - corner).dot(normal);
        if height < N::ZERO {
            if let Some(scale) = (weight * height).checked_div(normal.dot(normal)) {
                lift = lift - normal * scale;
            }
        }
    }
    lift
}

pub fn intersect<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> Option<Hit<N>> {
    surface(ray).filter(|(t, _)| interval.contains(*t)).map(|(t, normal)| Hit { t, normal })
}

pub fn occluded<N: Number>(ray: &Ray<N>, interval: ScaledInterval<N>) -> bool {
    surface(ray).is_some_and(|(t, _)| interval.contains(t))
}

/// The crossing, at any `t` (an open surface: no solid may use it, see `Primitive::is_closed`).
pub fn crossings<N: Number>(ray: &Ray<N>) -> [Option<(N, Vector3<N>)>; 1] {
    [surface(ray)]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn normals(corners: [[f64; 3]; 3]) -> VertexNormals {
        VertexNormals::from_f64(corners).unwrap()
    }

    /// Normals all along the plane's: a flat surface, nothing to lift. Normals leaning out from
    /// the middle (a cap of a sphere): the middle lifted above the plane, a corner not at all.
    /// Normals leaning in (a hollow): the facet lies above the corners' planes, nothing lifted.
    #[test]
    fn the_lift_follows_the_corner_normals() {
        let third = 1.0 / 3.0;
        let flat = terminator_lift::<f64>(third, third, normals([[0.0, 0.0, 1.0]; 3]));
        assert_eq!(flat.to_array(), [0.0; 3]);
        let cap = normals([[-0.5, -0.5, 1.0], [0.5, -0.2, 1.0], [-0.2, 0.5, 1.0]]);
        let middle = terminator_lift::<f64>(third, third, cap);
        assert!(middle.z > 0.01 && middle.z < 0.5, "{middle:?}");
        assert_eq!(terminator_lift::<f64>(0.0, 0.0, cap).to_array(), [0.0; 3], "a corner lies on its own plane");
        let hollow = normals([[0.5, 0.5, 1.0], [-0.5, 0.2, 1.0], [0.2, -0.5, 1.0]]);
        assert_eq!(terminator_lift::<f64>(third, third, hollow).to_array(), [0.0; 3]);
        let in_f32 = terminator_lift::<f32>(third as f32, third as f32, cap);
        assert!((f64::from(in_f32.z) - middle.z).abs() < 1e-6, "{in_f32:?}");
    }
}
