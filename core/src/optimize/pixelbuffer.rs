//! Pixelbuffer (§4.7.2, `rendervolume` and `pgatrace`): before tracing, the sink is flooded with
//! one colour and every object's projected bounding volume is filled with another; each row is
//! read back just before it is traced, and a pixel still holding the flood colour gets the
//! background without a ray.
//!
//! The fill is our own conservative scan conversion of the convex hull of the 8 projected
//! vertices (for a box in front of the eye that is exactly the union of the thesis's six
//! quads): row r is filled from the leftmost to the rightmost point of the hull within the band
//! of rows [r − MARGIN, r + MARGIN], widened by MARGIN, so a pixel whose sample point is within
//! half a pixel of the hull is always filled. Every hull edge is a segment between two of the
//! 8 points, and every such segment lies in the hull, so clipping all 28 segments (and the
//! points) to the band gives exactly the hull's x-range in the band. Volumes without a
//! projection (at or behind the eye, parallel rays along the view plane) fill the whole screen.

use super::projection::{Polygon, Screen, MARGIN};

/// The inclusive column span of row `row` covered by the convex `polygon` (with the margin).
pub fn hull_span(polygon: &Polygon, row: u16, width: u16) -> Option<(u16, u16)> {
    let (low, high) = (f64::from(row) - MARGIN, f64::from(row) + MARGIN);
    let (mut left, mut right) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut take = |x: f64| {
        left = left.min(x);
        right = right.max(x);
    };
    let points = polygon.vertices();
    for (i, &a) in points.iter().enumerate() {
        let b = points[(i + 1) % points.len()];
        let dy = b[1] - a[1];
        if dy == 0.0 {
            if a[1] >= low && a[1] <= high {
                take(a[0]);
                take(b[0]);
            }
            continue;
        }
        // s where the edge crosses the band's edges, clipped to [0, 1].
        let (s1, s2) = ((low - a[1]) / dy, (high - a[1]) / dy);
        let (s_low, s_high) = (s1.min(s2).max(0.0), s1.max(s2).min(1.0));
        if s_low <= s_high {
            take(a[0] + s_low * (b[0] - a[0]));
            take(a[0] + s_high * (b[0] - a[0]));
        }
    }
    if left > right {
        return None;
    }
    Screen::pixel_range(left, right, width)
}
