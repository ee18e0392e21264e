//! Pixelbuffer (§4.7.2, `rendervolume` and `pgatrace`): before tracing, the sink is flooded with
//! one colour and every object's projected bounding volume is filled with another; each row is
//! read back just before it is traced, and a pixel still holding the flood colour gets the
//! background without a ray.
//!
//! Our fill (the default tuning) is each object's extent octagon (`Extent::row_span`): the
//! silhouette's rectangle cut by its two diagonal ranges, prepared once with Extents, filled
//! per frame in integer arithmetic, no projection (it was most of a Cortex-M frame in
//! software `f64`). With the thesis's tuning (`Tuning::THESIS`), the thesis's volumes:
//!
//! The volume fill is our own conservative scan conversion of the convex hull of the 8 projected
//! vertices (for a box in front of the eye that is exactly the union of the thesis's six
//! quads): row r is filled from the leftmost to the rightmost point of the hull within the band
//! of rows [r − MARGIN, r + MARGIN], widened by MARGIN, so a pixel whose sample point is within
//! half a pixel of the hull is always filled. Every hull edge is a segment between two of the
//! 8 points, and every such segment lies in the hull, so clipping all 28 segments (and the
//! points) to the band gives exactly the hull's x-range in the band. A volume reaching the eye
//! plane is clipped there first (`projection`, B16); volumes without a projection (the eye in
//! or at them, parallel rays along the view plane) fill the whole screen.

use super::projection::{Polygon, Screen, MARGIN};

/// The inclusive column span of row `row` covered by the convex `polygon` (with the margin).
pub fn hull_span(polygon: &Polygon, row: u16, width: u16) -> Option<(u16, u16)> {
    band_span(polygon, 1, f64::from(row), f64::from(row), width)
}

/// The inclusive pixel range along the other axis covered by the polygon within the band
/// `first..=last` (with the margin) along `axis` (0: columns, 1: rows), clipped to `count`.
pub fn band_span(polygon: &Polygon, axis: usize, first: f64, last: f64, count: u16) -> Option<(u16, u16)> {
    let other = 1 - axis;
    let (low, high) = (first - MARGIN, last + MARGIN);
    let (mut left, mut right) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut take = |x: f64| {
        left = left.min(x);
        right = right.max(x);
    };
    let points = polygon.vertices();
    for (i, &a) in points.iter().enumerate() {
        let b = points[(i + 1) % points.len()];
        // Most edges of a convex polygon miss a one-row band: skip them before dividing (two
        // software divisions per edge and row were most of the fill's cost on a Cortex-M).
        let (edge_low, edge_high) = if a[axis] <= b[axis] { (a[axis], b[axis]) } else { (b[axis], a[axis]) };
        if edge_high < low || edge_low > high {
            continue;
        }
        let dy = b[axis] - a[axis];
        if dy == 0.0 {
            if a[axis] >= low && a[axis] <= high {
                take(a[other]);
                take(b[other]);
            }
            continue;
        }
        // s where the edge crosses the band's edges, clipped to [0, 1].
        let (s1, s2) = ((low - a[axis]) / dy, (high - a[axis]) / dy);
        let (s_low, s_high) = (s1.min(s2).max(0.0), s1.max(s2).min(1.0));
        if s_low <= s_high {
            take(a[other] + s_low * (b[other] - a[other]));
            take(a[other] + s_high * (b[other] - a[other]));
        }
    }
    if left > right {
        return None;
    }
    Screen::pixel_range(left, right, count)
}
