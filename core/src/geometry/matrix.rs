//! The thesis's 4x4 transformation matrix in `f64`, used to compose an object's transform at
//! scene-load time (§1.5.1, BUILD.C).
//!
//! Row-vector convention: a point maps as `[x y z 1] · M`, translation sits in row 3, and every
//! operation post-multiplies (`M ← M · X`), so statements apply in the order they are written.

/// A 4x4 matrix, `rows[r][c]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Matrix4 {
    pub rows: [[f64; 4]; 4],
}

impl Default for Matrix4 {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Matrix4 {
    pub const IDENTITY: Self = Self {
        rows: [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    };

    /// `matscale`: `M ← M · diag(sx, sy, sz, 1)`.
    pub fn scale(&mut self, factors: [f64; 3]) {
        for row in &mut self.rows {
            for (entry, factor) in row.iter_mut().zip(factors) {
                *entry *= factor;
            }
        }
    }

    /// `mattranslate`: `M ← M · T` with `T`'s row 3 = (tx, ty, tz, 1).
    pub fn translate(&mut self, offset: [f64; 3]) {
        for row in &mut self.rows {
            let w = row[3];
            for (entry, component) in row.iter_mut().zip(offset) {
                *entry += w * component;
            }
        }
    }

    /// `matrotx`/`matroty`/`matrotz`: a right-handed rotation by `degrees` about `axis`
    /// (0 = x, 1 = y, 2 = z), anticlockwise looking down the positive axis (eqs 1.12–1.14).
    /// The thesis converts with 57.295779; we use the exact π/180 (see docs/deviations.md).
    pub fn rotate(&mut self, axis: usize, degrees: f64) {
        let radians = degrees * (core::f64::consts::PI / 180.0);
        let (sin, cos) = (libm::sin(radians), libm::cos(radians));
        // The two columns that mix, in the order that makes the rotation right-handed.
        let (first, second) = match axis {
            0 => (1, 2),
            1 => (2, 0),
            _ => (0, 1),
        };
        for row in &mut self.rows {
            let a = row[first];
            let b = row[second];
            row[first] = a * cos - b * sin;
            row[second] = b * cos + a * sin;
        }
    }

    /// `p · M` for a point (translation applied, no w divide, as `transformpoint`).
    pub fn transform_point(&self, p: [f64; 3]) -> [f64; 3] {
        let [r0, r1, r2, r3] = &self.rows;
        let column = |j: usize| p[0] * r0[j] + p[1] * r1[j] + p[2] * r2[j] + r3[j];
        [column(0), column(1), column(2)]
    }

    /// The inverse of the affine part (upper 3x3 and row 3), or `None` when it is singular or
    /// its inverse is not finite. The thesis ignored a failed inversion (digest §11 B19).
    pub fn affine_inverse(&self) -> Option<Self> {
        let m = &self.rows;
        // Cofactors of the upper 3x3 (row-vector layout, inverse = adjugate / determinant).
        let c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
        let c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
        let c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
        let determinant = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
        if determinant == 0.0 || !determinant.is_finite() {
            return None;
        }
        let r = 1.0 / determinant;
        let mut inverse = [[0.0; 4]; 4];
        inverse[0][0] = c00 * r;
        inverse[1][0] = c01 * r;
        inverse[2][0] = c02 * r;
        inverse[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * r;
        inverse[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * r;
        inverse[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * r;
        inverse[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * r;
        inverse[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * r;
        inverse[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * r;
        // Row 3: -t · inverse(3x3).
        let translation: [f64; 3] =
            core::array::from_fn(|j| -(m[3][0] * inverse[0][j] + m[3][1] * inverse[1][j] + m[3][2] * inverse[2][j]));
        inverse[3] = [translation[0], translation[1], translation[2], 1.0];
        if inverse.iter().flatten().all(|v| v.is_finite()) {
            Some(Self { rows: inverse })
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
    }

    #[test]
    fn statements_apply_in_written_order() {
        // scale, then rotate about z by 90, then translate: (1,0,0) -> (2,0,0) -> (0,2,0) -> (0,2,5)
        let mut m = Matrix4::IDENTITY;
        m.scale([2.0, 1.0, 1.0]);
        m.rotate(2, 90.0);
        m.translate([0.0, 0.0, 5.0]);
        assert!(close(m.transform_point([1.0, 0.0, 0.0]), [0.0, 2.0, 5.0]));
    }

    #[test]
    fn rotations_are_right_handed() {
        let mut x = Matrix4::IDENTITY;
        x.rotate(0, 90.0);
        assert!(close(x.transform_point([0.0, 1.0, 0.0]), [0.0, 0.0, 1.0]));
        let mut y = Matrix4::IDENTITY;
        y.rotate(1, 90.0);
        assert!(close(y.transform_point([0.0, 0.0, 1.0]), [1.0, 0.0, 0.0]));
        let mut z = Matrix4::IDENTITY;
        z.rotate(2, 90.0);
        assert!(close(z.transform_point([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]));
    }

    #[test]
    fn inverse_undoes_the_transform_and_singular_is_rejected() {
        let mut m = Matrix4::IDENTITY;
        m.scale([3.0, 0.5, 2.0]);
        m.rotate(0, 30.0);
        m.rotate(1, -70.0);
        m.translate([10.0, -4.0, 7.0]);
        let inverse = m.affine_inverse().unwrap();
        let p = [0.3, -1.2, 4.0];
        assert!(close(inverse.transform_point(m.transform_point(p)), p));
        let mut singular = Matrix4::IDENTITY;
        singular.scale([1.0, 0.0, 1.0]);
        assert_eq!(singular.affine_inverse(), None);
    }
}
