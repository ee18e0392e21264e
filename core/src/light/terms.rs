//! The lighting terms common to both modes (digest §6.2): diffuse `max(0, N·L)` and Blinn's
//! halfway-vector specular `(N·H)^pwr` with `H = normalize(L − D)`.
//!
//! The thesis called `pow` with unclamped N·H (§11 B18); here N·H is clamped at 0 and the power
//! is an integer (the scene's `pwr` rounded), which a fixed-point type can compute.

use crate::geometry::Vector3;
use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lighting<N> {
    pub diffuse: N,
    pub specular: N,
}

/// `normal`, `to_light` and `view` (eye toward the surface) are unit vectors. A shadowed point
/// or one facing away from the light gets neither term.
pub fn lighting<N: Number>(normal: Vector3<N>, to_light: Vector3<N>, view: Vector3<N>, power: u32, shadowed: bool) -> Lighting<N> {
    let diffuse = normal.dot(to_light);
    if shadowed || diffuse <= N::ZERO {
        return Lighting { diffuse: N::ZERO, specular: N::ZERO };
    }
    let specular = match (to_light - view).normalized() {
        Some(halfway) => normal.dot(halfway).max(N::ZERO).powi(power),
        None => N::ZERO,
    };
    Lighting { diffuse, specular }
}
