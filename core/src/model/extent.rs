//! A screen extent (§4.7.3, `calcextent`): the rectangle, in image coordinates (column from
//! the left, row from the top), outside which an object (or a part of a solid, §3.3.6) cannot
//! be seen. Here, below the layers that make one (`optimize::extents`), because a solid's
//! prepared nodes carry theirs.

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

impl crate::storage::Unset for Extent {
    const UNSET: Self = Self { first_column: 0, last_column: 0, first_row: 0, last_row: 0, diagonal: [0; 4] };
}

impl Extent {
    pub const EMPTY: Self = Self { first_column: 1, last_column: 0, first_row: 1, last_row: 0, diagonal: [1, 0, 1, 0] };
    /// Every pixel of any screen: what is not yet known to be smaller.
    pub const EVERYWHERE: Self = Self { first_column: 0, last_column: u16::MAX, first_row: 0, last_row: u16::MAX, diagonal: [0, u16::MAX, 0, u16::MAX] };

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

    /// Whether no pixel lies in it: the rectangle or a diagonal range is empty (an overlap's
    /// may be empty by its diagonals alone).
    fn covers_nothing(&self) -> bool {
        let [s1, s2, d1, d2] = self.diagonal;
        self.is_empty() || s1 > s2 || d1 > d2
    }

    /// Whether the pixel lies in the octagon: the rectangle and both diagonal ranges.
    #[inline]
    pub fn covers(&self, column: u16, row: u16, height: u16) -> bool {
        self.contains(column, row) && self.diagonals_contain(column, row, height)
    }

    /// The smallest extent around both (every range the hull of the two): what a union of two
    /// parts may cover (§3.3.6, ∪).
    pub fn hull(self, other: Self) -> Self {
        if self.covers_nothing() {
            return other;
        }
        if other.covers_nothing() {
            return self;
        }
        let [a, b] = [self.diagonal, other.diagonal];
        Self {
            first_column: self.first_column.min(other.first_column),
            last_column: self.last_column.max(other.last_column),
            first_row: self.first_row.min(other.first_row),
            last_row: self.last_row.max(other.last_row),
            diagonal: [a[0].min(b[0]), a[1].max(b[1]), a[2].min(b[2]), a[3].max(b[3])],
        }
    }

    /// Where both may be seen (every range cut to both): what an intersection of two parts may
    /// cover (§3.3.6, ∩). A pixel is in it exactly when it is in both.
    pub fn overlap(self, other: Self) -> Self {
        let [a, b] = [self.diagonal, other.diagonal];
        Self {
            first_column: self.first_column.max(other.first_column),
            last_column: self.last_column.min(other.last_column),
            first_row: self.first_row.max(other.first_row),
            last_row: self.last_row.min(other.last_row),
            diagonal: [a[0].max(b[0]), a[1].min(b[1]), a[2].max(b[2]), a[3].min(b[3])],
        }
    }
}
