//! The directions of the ray tree's secondary rays (thesis §5.2.2, Whitted 1980): the mirror
//! direction, and the refracted direction by Snell's law with total internal reflection.

use super::Vector3;
use crate::number::Number;

/// The mirror image of the unit `direction` about the unit `normal` (which faces against the
/// direction): `D − 2(N·D)N`, normalised again so that rounding does not accumulate down the tree.
pub fn reflected<N: Number>(direction: Vector3<N>, normal: Vector3<N>) -> Vector3<N> {
    let cosine = normal.dot(direction);
    let mirror = direction - normal * (cosine + cosine);
    mirror.normalized().unwrap_or(mirror)
}

/// The direction of the unit `direction` refracted at a surface with unit `normal` (facing
/// against the direction) from a medium of index `from` into one of index `into`; `None` for
/// total internal reflection. `T = ηD + (η cos i − √k) N`, `η = from/into`,
/// `k = 1 − η²(1 − cos² i)`.
pub fn refracted<N: Number>(direction: Vector3<N>, normal: Vector3<N>, from: N, into: N) -> Option<Vector3<N>> {
    let eta = from.checked_div(into)?;
    let cosine = -normal.dot(direction);
    let k = N::ONE - eta * eta * (N::ONE - cosine * cosine);
    if k < N::ZERO {
        return None;
    }
    let bent = direction * eta + normal * (eta * cosine - k.sqrt());
    Some(bent.normalized().unwrap_or(bent))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
        Vector3::from_f64([x, y, z])
    }

    #[test]
    fn a_mirror_keeps_the_tangent_and_turns_the_normal_part() {
        let d = v(1.0, -1.0, 0.0).normalized().unwrap();
        let r = reflected(d, v(0.0, 1.0, 0.0));
        assert!((r.x - d.x).abs() < 1e-15 && (r.y + d.y).abs() < 1e-15 && r.z == 0.0, "{r:?}");
    }

    #[test]
    fn index_one_changes_no_direction() {
        let d = v(0.3, -0.8, 0.2).normalized().unwrap();
        let t = refracted(d, v(0.0, 1.0, 0.0), 1.0, 1.0).unwrap();
        assert!((t - d).length() < 1e-15, "{t:?}");
    }

    #[test]
    fn snell_holds_and_grazing_light_inside_glass_is_totally_reflected() {
        let n = v(0.0, 1.0, 0.0);
        let d = v(0.5, -(0.75f64).sqrt(), 0.0); // 30 degrees from the normal
        let t = refracted(d, n, 1.0, 1.5).unwrap();
        // sin(out) = sin(in) / 1.5
        assert!((t.x - 0.5 / 1.5).abs() < 1e-12, "{t:?}");
        // From glass at 60 degrees: beyond the critical angle asin(1/1.5) = 41.8 degrees.
        let steep = v((0.75f64).sqrt(), -0.5, 0.0);
        assert_eq!(refracted(steep, n, 1.5, 1.0), None);
        // Just below the critical angle it still leaves.
        let critical = libm::asin(1.0 / 1.5) - 1e-6;
        assert!(refracted(v(libm::sin(critical), -libm::cos(critical), 0.0), n, 1.5, 1.0).is_some());
    }
}
