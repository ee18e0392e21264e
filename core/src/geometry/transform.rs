//! An affine transform in the tracer's number type: the upper 3x3 and the translation row of a
//! [`Matrix4`]. Only the inverse (`object_from_world`) is kept per object; normals go back to
//! world space through its transpose (the inverse transpose of the forward matrix), which the
//! thesis got wrong by using the forward matrix (digest §11 B2).

use super::{Matrix4, Ray, Vector3};
use crate::number::Number;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AffineTransform<N> {
    /// The linear part stored by columns, `columns[c][r]` = `linear[r][c]` in the row-vector
    /// convention `p' = p · linear + translation`: each component of a transformed vector is then
    /// one `dot3` with a stored column, with nothing gathered (ray directions and origins are
    /// transformed once per ray–object test; normals, which need rows, once per hit).
    columns: [[N; 3]; 3],
    pub translation: [N; 3],
}

impl<N: Copy> AffineTransform<N> {
    /// From the linear part by columns (`columns[c][r]`) and the translation.
    pub const fn from_parts(columns: [[N; 3]; 3], translation: [N; 3]) -> Self {
        Self { columns, translation }
    }

    /// The linear part by columns, as [`AffineTransform::from_parts`] takes it.
    pub fn columns(&self) -> [[N; 3]; 3] {
        self.columns
    }
}

impl<N: Number> AffineTransform<N> {
    pub fn from_matrix(matrix: &Matrix4) -> Self {
        let m = &matrix.rows;
        Self {
            columns: core::array::from_fn(|c| core::array::from_fn(|r| N::from_f64(m[r][c]))),
            translation: core::array::from_fn(|c| N::from_f64(m[3][c])),
        }
    }

    /// `linear[row][column]` of the row-vector convention.
    pub fn linear(&self, row: usize, column: usize) -> N {
        self.columns[column][row]
    }

    /// `transformvector`: `v · linear`.
    #[inline]
    pub fn vector(&self, v: Vector3<N>) -> Vector3<N> {
        let v = [v.x, v.y, v.z];
        let c = &self.columns;
        Vector3::new(N::dot3(v, c[0]), N::dot3(v, c[1]), N::dot3(v, c[2]))
    }

    /// The vector `w` with `w · linear = v` (Cramer's rule over the stored columns); `None` for
    /// a singular linear part or a quotient beyond the type.
    pub fn vector_preimage(&self, v: Vector3<N>) -> Option<Vector3<N>> {
        let [a, b, c] = self.columns.map(|[x, y, z]| Vector3::new(x, y, z));
        let (bc, ca, ab) = (b.cross(c), c.cross(a), a.cross(b));
        let determinant = a.dot(bc);
        let sum = bc * v.x + ca * v.y + ab * v.z;
        Some(Vector3::new(sum.x.checked_div(determinant)?, sum.y.checked_div(determinant)?, sum.z.checked_div(determinant)?))
    }

    /// `transformpoint`: `p · linear + translation`.
    #[inline]
    pub fn point(&self, p: Vector3<N>) -> Vector3<N> {
        let t = &self.translation;
        self.vector(p) + Vector3::new(t[0], t[1], t[2])
    }

    /// The ray in this transform's target space. The direction is not renormalised, so `t`
    /// means the same in both spaces (§4.4).
    #[inline]
    pub fn ray(&self, ray: &Ray<N>) -> Ray<N> {
        Ray { origin: self.point(ray.origin), direction: self.vector(ray.direction) }
    }

    /// `linear · v` (a column vector): with `self` = object_from_world this takes an object
    /// normal to world space through the inverse transpose of world_from_object.
    #[inline]
    pub fn transposed_vector(&self, v: Vector3<N>) -> Vector3<N> {
        let c = &self.columns;
        let row = |r: usize| N::dot3([c[0][r], c[1][r], c[2][r]], [v.x, v.y, v.z]);
        Vector3::new(row(0), row(1), row(2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The preimage taken back through the transform is the vector; a singular map has none.
    #[test]
    fn the_preimage_of_a_vector_maps_back_onto_it() {
        let transform = AffineTransform::<f64>::from_parts([[2.0, 0.5, -1.0], [0.3, -3.0, 0.25], [1.5, 0.0, 4.0]], [1.0, 2.0, 3.0]);
        let v = Vector3::new(0.7, -1.3, 2.9);
        let w = transform.vector_preimage(v).unwrap();
        let back = transform.vector(w);
        for (a, b) in back.to_array().into_iter().zip(v.to_array()) {
            assert!((a - b).abs() < 1e-12, "{back:?} against {v:?}");
        }
        let singular = AffineTransform::<f64>::from_parts([[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 1.0, 0.0]], [0.0; 3]);
        assert_eq!(singular.vector_preimage(v), None);
    }
}
