//! A 3-vector in the tracer's number type.

use core::ops::{Add, Mul, Neg, Sub};

use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vector3<N> {
    pub x: N,
    pub y: N,
    pub z: N,
}

impl<N: crate::storage::Unset> crate::storage::Unset for Vector3<N> {
    const UNSET: Self = Self { x: N::UNSET, y: N::UNSET, z: N::UNSET };
}

impl<N: Number> Vector3<N> {
    pub const fn new(x: N, y: N, z: N) -> Self {
        Self { x, y, z }
    }

    pub fn zero() -> Self {
        Self::new(N::ZERO, N::ZERO, N::ZERO)
    }

    pub fn from_f64(v: [f64; 3]) -> Self {
        Self::new(N::from_f64(v[0]), N::from_f64(v[1]), N::from_f64(v[2]))
    }

    pub fn to_f64(self) -> [f64; 3] {
        [self.x.to_f64(), self.y.to_f64(), self.z.to_f64()]
    }

    #[inline]
    pub fn to_array(self) -> [N; 3] {
        [self.x, self.y, self.z]
    }

    #[inline]
    pub fn dot(self, other: Self) -> N {
        N::dot3(self.to_array(), other.to_array())
    }

    /// `self × other`.
    pub fn cross(self, other: Self) -> Self {
        Self::new(self.y * other.z - self.z * other.y, self.z * other.x - self.x * other.z, self.x * other.y - self.y * other.x)
    }

    #[inline]
    pub fn length(self) -> N {
        N::length3(self.to_array())
    }

    /// The unit vector in the same direction, or `None` for the zero vector. In fixed point the
    /// vector is first scaled by a power of two to a largest component in [1, 2) (in floating
    /// point that would change nothing): it keeps a short vector (the world normal
    /// of a large object has components of about one over its size) from losing the
    /// significant bits of its squares (a Q32.32 normal was 8·10⁻⁴ too long at size 4000).
    // Inline: out of line, its `Option<Vector3>` went back through memory at each of the
    // four calls a hit pixel makes (137 k instructions of a 2.93 M Cortex-M4F frame).
    #[inline]
    pub fn normalized(self) -> Option<Self> {
        let scaled = if N::FLOATING_POINT { self } else { self.times_power_of_two(-self.largest_component().binary_exponent()?) };
        let reciprocal = N::ONE.checked_div(scaled.length())?;
        Some(scaled * reciprocal)
    }

    /// The largest magnitude among the components.
    pub fn largest_component(self) -> N {
        self.x.abs().max(self.y.abs()).max(self.z.abs())
    }

    /// Each component times 2^`exponent` (see [`Number::times_power_of_two`]).
    pub fn times_power_of_two(self, exponent: i32) -> Self {
        Self::new(self.x.times_power_of_two(exponent), self.y.times_power_of_two(exponent), self.z.times_power_of_two(exponent))
    }

    pub fn component(self, axis: usize) -> N {
        match axis {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }
}

impl<N: Number> Add for Vector3<N> {
    type Output = Self;
    #[inline]
    fn add(self, other: Self) -> Self {
        Self::new(self.x + other.x, self.y + other.y, self.z + other.z)
    }
}

impl<N: Number> Sub for Vector3<N> {
    type Output = Self;
    #[inline]
    fn sub(self, other: Self) -> Self {
        Self::new(self.x - other.x, self.y - other.y, self.z - other.z)
    }
}

impl<N: Number> Neg for Vector3<N> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl<N: Number> Mul<N> for Vector3<N> {
    type Output = Self;
    #[inline]
    fn mul(self, scale: N) -> Self {
        Self::new(self.x * scale, self.y * scale, self.z * scale)
    }
}

#[cfg(all(test, feature = "fixed-point"))]
mod tests {
    use super::Vector3;
    use crate::number::{Fixed, Fixed16, Number};

    /// A short vector (the world normal of an object 4000 units across) normalises to unit
    /// length in fixed point; before scaling it first, Q32.32 was 8·10⁻⁴ too long.
    fn check_short_vector<N: Number>(tolerance: f64, direction_tolerance: f64) {
        let short = Vector3::<N>::from_f64([7.972e-5, 0.0, 2.369e-4]);
        let unit = short.normalized().unwrap().to_f64();
        let length = (unit[0] * unit[0] + unit[1] * unit[1] + unit[2] * unit[2]).sqrt();
        assert!((length - 1.0).abs() < tolerance, "{} {length}", N::NAME);
        // The direction is kept, to the conversion of the input (2⁻³² on 8·10⁻⁵ in Q32.32; only
        // five LSBs in Q16.16).
        assert!((unit[0] / unit[2] - 7.972e-5 / 2.369e-4).abs() < direction_tolerance, "{} {unit:?}", N::NAME);
    }

    #[test]
    fn short_vectors_normalise_to_unit_length() {
        check_short_vector::<f64>(1e-15, 1e-14);
        check_short_vector::<f32>(1e-6, 1e-6);
        check_short_vector::<Fixed>(1e-8, 1e-5);
        check_short_vector::<Fixed16>(1e-4, 0.1);
        assert_eq!(Vector3::<Fixed>::zero().normalized(), None);
    }

    #[test]
    fn scaling_by_a_power_of_two_leaves_float_results_unchanged() {
        let v = Vector3::<f64>::from_f64([1e-3, -2.5e-4, 7.0e-4]);
        let length = Number::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        assert_eq!(v.normalized().unwrap(), v * (1.0 / length));
    }
}
