//! The two roots of `A t² + 2 b t + c = 0` in the half-b form the thesis uses (§4.5), computed
//! stably: `q = −b − sign(b)·√Δ`, roots `c / q` and `q / A` (no cancellation between `b` and
//! `√Δ`).

use crate::number::Number;

/// Both roots, nearer first, given the discriminant `Δ = b² − A c` (already known to be ≥ 0).
/// A root that cannot be formed (zero divisor) is `None`.
#[inline]
pub fn roots<N: Number>(a: N, b: N, c: N, discriminant: N) -> [Option<N>; 2] {
    let root_of_discriminant = discriminant.sqrt();
    let q = if b < N::ZERO { -b + root_of_discriminant } else { -b - root_of_discriminant };
    let first = c.checked_div(q);
    let second = q.checked_div(a);
    match (first, second) {
        (Some(x), Some(y)) if y < x => [Some(y), Some(x)],
        pair => [pair.0, pair.1],
    }
}

/// The discriminant of a ray and a unit circle or sphere, `A·(1 − |p − d·b/A|²)`: the squared
/// distance from the centre to the ray's line subtracted from the radius, which keeps its
/// precision for far, small objects where `b² − A c` cancels (precision notes).
/// `p` and `d` are the components that take part (3 for the sphere, x and y for the cylinder).
#[inline]
pub fn unit_discriminant<N: Number>(p: [N; 3], d: [N; 3], a: N, b: N) -> Option<N> {
    let along = b.checked_div(a)?;
    let perpendicular = [p[0] - d[0] * along, p[1] - d[1] * along, p[2] - d[2] * along];
    let distance_squared = N::dot3(perpendicular, perpendicular);
    Some(a * (N::ONE - distance_squared))
}
