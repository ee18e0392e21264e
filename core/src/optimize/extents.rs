//! Extents (§4.7.3, `calcextent`): the screen rectangle of each object's projected bounding
//! volume, four `u16`s in image coordinates (column from the left, row from the top).
//! A pixel outside the rectangle skips the object without a ray–object test.

use super::projection::{Projected, Screen, MARGIN};

pub use crate::model::Extent;

impl Extent {
    pub fn whole(screen: &Screen) -> Self {
        Self { first_column: 0, last_column: screen.width - 1, first_row: 0, last_row: screen.height - 1, diagonal: [0, u16::MAX, 0, u16::MAX] }
    }

    /// The rectangle of projected points (with the projection margin), or the whole screen for
    /// a volume without a projection (the eye in or at it, B16; rays along the view plane, B17).
    pub fn of(screen: &Screen, projected: &Projected) -> Self {
        let points = match projected {
            Projected::Points(points) => points,
            Projected::Whole => return Self::whole(screen),
            Projected::Invisible => return Self::EMPTY,
        };
        let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points.vertices() {
            for k in 0..2 {
                low[k] = low[k].min(p[k]);
                high[k] = high[k].max(p[k]);
            }
        }
        let offset = f64::from(screen.height - 1);
        let (mut sums, mut differences) = ((f64::INFINITY, f64::NEG_INFINITY), (f64::INFINITY, f64::NEG_INFINITY));
        for p in points.vertices() {
            let (sum, difference) = (p[0] + p[1], p[0] - p[1] + offset);
            sums = (sums.0.min(sum), sums.1.max(sum));
            differences = (differences.0.min(difference), differences.1.max(difference));
        }
        // A pixel within MARGIN of the silhouette in x and in y is within 2·MARGIN diagonally.
        let range = |(low, high): (f64, f64)| {
            let first = libm::ceil(low - 2.0 * MARGIN).clamp(0.0, 65535.0) as u16;
            let last = libm::floor(high + 2.0 * MARGIN).clamp(0.0, 65535.0) as u16;
            (first, last)
        };
        let ((s1, s2), (d1, d2)) = (range(sums), range(differences));
        match (Screen::pixel_range(low[0], high[0], screen.width), Screen::pixel_range(low[1], high[1], screen.height)) {
            (Some((first_column, last_column)), Some((first_row, last_row))) if s1 <= s2 && d1 <= d2 => {
                Self { first_column, last_column, first_row, last_row, diagonal: [s1, s2, d1, d2] }
            }
            _ => Self::EMPTY,
        }
    }
}
