//! Extents (§4.7.3, `calcextent`): the screen rectangle of each object's projected bounding
//! volume, four `u16`s in image coordinates (column from the left, row from the top).
//! A pixel outside the rectangle skips the object without a ray–object test.

use super::projection::{Projected, Screen, MARGIN};

/// Inclusive rectangle; `first_column > last_column` means empty (never entered). Beyond the
/// thesis, also the silhouette's range along both diagonals (`column + row`, and
/// `column − row + height − 1`), which makes the extent an octagon: 5% larger than a disc
/// instead of 27%, and tight around thin oblique objects.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Extent {
    pub first_column: u16,
    pub last_column: u16,
    pub first_row: u16,
    pub last_row: u16,
    pub diagonal: [u16; 4],
}

impl Extent {
    pub const EMPTY: Self = Self { first_column: 1, last_column: 0, first_row: 1, last_row: 0, diagonal: [1, 0, 1, 0] };

    pub fn whole(screen: &Screen) -> Self {
        Self { first_column: 0, last_column: screen.width - 1, first_row: 0, last_row: screen.height - 1, diagonal: [0, u16::MAX, 0, u16::MAX] }
    }

    /// Whether the pixel lies within the diagonal ranges.
    #[inline]
    pub fn diagonals_contain(&self, column: u16, row: u16, height: u16) -> bool {
        let sum = u32::from(column) + u32::from(row);
        let difference = u32::from(column) + u32::from(height - 1) - u32::from(row);
        // Destructured, not `map`ped: `array::map` compiled to a loop through the stack.
        let [s1, s2, d1, d2] = self.diagonal;
        let (s1, s2, d1, d2) = (u32::from(s1), u32::from(s2), u32::from(d1), u32::from(d2));
        sum >= s1 && sum <= s2 && difference >= d1 && difference <= d2
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

    /// The inclusive column span of `row` within the octagon (the rectangle cut by the two
    /// diagonal ranges); `None` when the row misses it. Integer arithmetic only: this is
    /// Pixelbuffer's fill (`optimize::pixelbuffer`).
    #[inline]
    pub fn row_span(&self, row: u16, height: u16) -> Option<(u16, u16)> {
        if row < self.first_row || row > self.last_row || self.first_column > self.last_column {
            return None;
        }
        let (row, offset) = (i32::from(row), i32::from(height) - 1);
        let [s1, s2, d1, d2] = self.diagonal;
        let (s1, s2, d1, d2) = (i32::from(s1), i32::from(s2), i32::from(d1), i32::from(d2));
        // s1 ≤ column + row ≤ s2 and d1 ≤ column − row + height − 1 ≤ d2.
        let first = i32::from(self.first_column).max(s1 - row).max(d1 + row - offset);
        let last = i32::from(self.last_column).min(s2 - row).min(d2 + row - offset);
        (first <= last).then(|| (first.clamp(0, 65535) as u16, last.clamp(0, 65535) as u16))
    }

    #[inline]
    pub fn contains(&self, column: u16, row: u16) -> bool {
        column >= self.first_column && column <= self.last_column && row >= self.first_row && row <= self.last_row
    }

    pub fn is_empty(&self) -> bool {
        self.first_column > self.last_column || self.first_row > self.last_row
    }
}
