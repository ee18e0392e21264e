//! Extents (§4.7.3, `calcextent`): the screen rectangle of each object's projected bounding
//! volume, four `u16`s in image coordinates (column from the left, row from the top).
//! A pixel outside the rectangle skips the object without a ray–object test.

use super::projection::{Projected, Screen};

/// Inclusive rectangle; `first_column > last_column` means empty (never entered).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Extent {
    pub first_column: u16,
    pub last_column: u16,
    pub first_row: u16,
    pub last_row: u16,
}

impl Extent {
    pub const EMPTY: Self = Self { first_column: 1, last_column: 0, first_row: 1, last_row: 0 };

    pub fn whole(screen: &Screen) -> Self {
        Self { first_column: 0, last_column: screen.width - 1, first_row: 0, last_row: screen.height - 1 }
    }

    /// The rectangle of projected points (with the projection margin), or the whole screen for
    /// a volume without a projection (digest B16, B17).
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
        match (Screen::pixel_range(low[0], high[0], screen.width), Screen::pixel_range(low[1], high[1], screen.height)) {
            (Some((first_column, last_column)), Some((first_row, last_row))) => Self { first_column, last_column, first_row, last_row },
            _ => Self::EMPTY,
        }
    }

    #[inline]
    pub fn contains(&self, column: u16, row: u16) -> bool {
        column >= self.first_column && column <= self.last_column && row >= self.first_row && row <= self.last_row
    }

    pub fn is_empty(&self) -> bool {
        self.first_column > self.last_column || self.first_row > self.last_row
    }
}
