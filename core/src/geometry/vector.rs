//! A 3-vector in the tracer's number type.

use core::ops::{Add, Mul, Neg, Sub};

use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vector3<N> {
    pub x: N,
    pub y: N,
    pub z: N,
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

    pub fn to_array(self) -> [N; 3] {
        [self.x, self.y, self.z]
    }

    pub fn dot(self, other: Self) -> N {
        N::dot3(self.to_array(), other.to_array())
    }

    pub fn length(self) -> N {
        N::length3(self.to_array())
    }

    /// The unit vector in the same direction, or `None` for the zero vector.
    pub fn normalized(self) -> Option<Self> {
        let length = self.length();
        let reciprocal = N::ONE.checked_div(length)?;
        Some(self * reciprocal)
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
    fn add(self, other: Self) -> Self {
        Self::new(self.x + other.x, self.y + other.y, self.z + other.z)
    }
}

impl<N: Number> Sub for Vector3<N> {
    type Output = Self;
    fn sub(self, other: Self) -> Self {
        Self::new(self.x - other.x, self.y - other.y, self.z - other.z)
    }
}

impl<N: Number> Neg for Vector3<N> {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl<N: Number> Mul<N> for Vector3<N> {
    type Output = Self;
    fn mul(self, scale: N) -> Self {
        Self::new(self.x * scale, self.y * scale, self.z * scale)
    }
}
