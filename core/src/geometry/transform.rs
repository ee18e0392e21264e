//! An affine transform in the tracer's number type: the upper 3x3 and the translation row of a
//! [`Matrix4`]. Only the inverse (`object_from_world`) is kept per object; normals go back to
//! world space through its transpose (the inverse transpose of the forward matrix), which the
//! thesis got wrong by using the forward matrix (digest §11 B2).

use super::{Matrix4, Ray, Vector3};
use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AffineTransform<N> {
    /// `linear[r][c]`, row-vector convention: `p' = p · linear + translation`.
    pub linear: [[N; 3]; 3],
    pub translation: [N; 3],
}

impl<N: Number> AffineTransform<N> {
    pub fn from_matrix(matrix: &Matrix4) -> Self {
        let m = &matrix.rows;
        Self {
            linear: core::array::from_fn(|r| core::array::from_fn(|c| N::from_f64(m[r][c]))),
            translation: core::array::from_fn(|c| N::from_f64(m[3][c])),
        }
    }

    /// `transformvector`: `v · linear`.
    pub fn vector(&self, v: Vector3<N>) -> Vector3<N> {
        let m = &self.linear;
        let column = |c: usize| N::dot3([v.x, v.y, v.z], [m[0][c], m[1][c], m[2][c]]);
        Vector3::new(column(0), column(1), column(2))
    }

    /// `transformpoint`: `p · linear + translation`.
    pub fn point(&self, p: Vector3<N>) -> Vector3<N> {
        let t = &self.translation;
        self.vector(p) + Vector3::new(t[0], t[1], t[2])
    }

    /// The ray in this transform's target space. The direction is not renormalised, so `t`
    /// means the same in both spaces (§4.4).
    pub fn ray(&self, ray: &Ray<N>) -> Ray<N> {
        Ray { origin: self.point(ray.origin), direction: self.vector(ray.direction) }
    }

    /// `linear · v` (a column vector): with `self` = object_from_world this takes an object
    /// normal to world space through the inverse transpose of world_from_object.
    pub fn transposed_vector(&self, v: Vector3<N>) -> Vector3<N> {
        let m = &self.linear;
        let row = |r: usize| N::dot3(m[r], [v.x, v.y, v.z]);
        Vector3::new(row(0), row(1), row(2))
    }
}
