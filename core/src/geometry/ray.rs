//! A ray: origin plus `t` times direction.

use super::Vector3;
use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<N> {
    pub origin: Vector3<N>,
    pub direction: Vector3<N>,
}

impl<N: Number> Ray<N> {
    pub fn at(&self, t: N) -> Vector3<N> {
        self.origin + self.direction * t
    }
}
