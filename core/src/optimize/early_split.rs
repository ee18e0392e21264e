//! Early split clipping (Ernst and Greiner, 2007) for the bounding volume hierarchy: a long
//! triangle across a scene's axes has a box far larger than itself, and every ray through the
//! box tests it. NFF's large concave polygons (the SPD's gears: 144 vertices, split into up to
//! 142 triangles spanning the face) are the worst case: a shadow ray leaving a face starts in
//! the boxes of dozens of its coplanar triangles. So, before the build, each triangle whose box
//! is large is cut in two at the middle of its box's longest axis, its pieces again, and each
//! piece's own box enters the hierarchy as a reference to the triangle: the boxes hug the
//! triangle, a triangle may be in several leaves.
//!
//! Which boxes are large: those whose surface area exceeds a threshold, the smallest (among
//! halvings of the largest box's area) that keeps the references within the storage the
//! caller gives, so the split is sized by the scene like everything else. The pieces are clipped
//! in `f64`; the hierarchy's margin covers their rounding.

use super::bvh::WorldBox;

/// A piece of a triangle cut by axis planes: a convex polygon of at most 3 + one vertex a cut.
type Piece = heapless::Vec<[f64; 3], { 3 + MAX_DEPTH }>;

/// The most cuts down one triangle (2⁸ pieces at most).
const MAX_DEPTH: usize = 8;

/// Fills `references` and `owners` with the objects' boxes, each triangle's (`triangle(index)`
/// its world vertices) cut into pieces while the references fit; returns how many there are
/// (at least `boxes.len()` when the storage holds that many, 0 otherwise).
pub fn split(
    count: usize,
    box_of: &impl Fn(usize) -> WorldBox,
    triangle: &impl Fn(usize) -> Option<[[f64; 3]; 3]>,
    references: &mut [WorldBox],
    owners: &mut [usize],
) -> usize {
    let capacity = references.len().min(owners.len());
    if capacity < count {
        return 0;
    }
    // The references at a threshold, or None beyond the capacity (counting stops there).
    let needed = |threshold: f64| -> Option<usize> {
        let mut needed = 0;
        for index in 0..count {
            match triangle(index) {
                Some(vertices) => cut(&Piece::from_iter(vertices), threshold, 0, &mut |_| needed += 1),
                None => needed += 1,
            }
            if needed > capacity {
                return None;
            }
        }
        Some(needed)
    };
    // The largest triangle's box area, halved while the references still fit.
    let largest = (0..count).filter(|index| triangle(*index).is_some()).map(|index| area(&box_of(index))).fold(0.0, f64::max);
    let mut threshold = f64::INFINITY;
    if largest > 0.0 && largest.is_finite() {
        let mut candidate = largest;
        // 64 halvings: far below any box that matters.
        for _ in 0..64 {
            if needed(candidate).is_none() {
                break;
            }
            threshold = candidate;
            candidate /= 2.0;
        }
    }
    let mut used = 0;
    for index in 0..count {
        let mut emit = |bounds: WorldBox| {
            if let (Some(reference), Some(owner)) = (references.get_mut(used), owners.get_mut(used)) {
                *reference = bounds;
                *owner = index;
                used += 1;
            }
        };
        match triangle(index) {
            Some(vertices) if threshold.is_finite() => cut(&Piece::from_iter(vertices), threshold, 0, &mut emit),
            _ => emit(box_of(index)),
        }
    }
    used
}

/// Emits the boxes of `piece` cut at the middle of its box's longest axis until each box's
/// area is at most `threshold` (or [`MAX_DEPTH`] cuts are made).
fn cut(piece: &Piece, threshold: f64, depth: usize, emit: &mut impl FnMut(WorldBox)) {
    let bounds = bounds(piece);
    if depth >= MAX_DEPTH || area(&bounds) <= threshold {
        emit(bounds);
        return;
    }
    let extent = [0, 1, 2].map(|k| bounds.1[k] - bounds.0[k]);
    let axis = (0..3).fold(0, |best, k| if extent[k] > extent[best] { k } else { best });
    let middle = (bounds.0[axis] + bounds.1[axis]) / 2.0;
    for keep_below in [true, false] {
        let half = clip(piece, axis, middle, keep_below);
        if !half.is_empty() {
            cut(&half, threshold, depth + 1, emit);
        }
    }
}

/// The part of the convex polygon on one side of the plane `p[axis] = at` (Sutherland and
/// Hodgman): below it (`keep_below`) or above it, the plane's points in both.
fn clip(piece: &Piece, axis: usize, at: f64, keep_below: bool) -> Piece {
    let inside = |p: &[f64; 3]| if keep_below { p[axis] <= at } else { p[axis] >= at };
    let mut out = Piece::new();
    let Some(mut previous) = piece.last().copied() else { return out };
    for current in piece {
        if inside(current) != inside(&previous) {
            let s = (at - previous[axis]) / (current[axis] - previous[axis]);
            let mut crossing = [0, 1, 2].map(|c| previous[c] + s * (current[c] - previous[c]));
            // Exactly on the plane, whatever the rounding of the other coordinates.
            crossing[axis] = at;
            let _ = out.push(crossing);
        }
        if inside(current) {
            let _ = out.push(*current);
        }
        previous = *current;
    }
    out
}

fn bounds(piece: &Piece) -> WorldBox {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for p in piece {
        for k in 0..3 {
            low[k] = low[k].min(p[k]);
            high[k] = high[k].max(p[k]);
        }
    }
    (low, high)
}

/// Half a box's surface area.
fn area((low, high): &WorldBox) -> f64 {
    super::bvh::area(*low, *high)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;

    /// A long thin triangle across the axes: cut into pieces whose boxes cover every point of
    /// it (sampled), with far less area in all than its own box.
    #[test]
    fn pieces_cover_the_triangle_and_hug_it() {
        let vertices = [[0.0, 0.0, 0.0], [100.0, 100.0, 50.0], [100.5, 99.0, 50.0]];
        let whole = bounds(&Piece::from_iter(vertices));
        let mut references = std::vec![([0.0; 3], [0.0; 3]); 64];
        let mut owners = std::vec![0; 64];
        let used = split(2, &|index| if index == 0 { whole } else { ([0.0; 3], [1.0; 3]) }, &|index| (index == 0).then_some(vertices), &mut references, &mut owners);
        assert!(used > 32 && used <= 64, "{used}");
        let pieces: Vec<WorldBox> = references[..used].iter().zip(&owners).filter(|(_, owner)| **owner == 0).map(|(r, _)| *r).collect();
        assert_eq!(owners[..used].iter().filter(|owner| **owner == 1).count(), 1, "the other object kept whole");
        let inside = |p: [f64; 3], (low, high): &WorldBox| (0..3).all(|k| low[k] <= p[k] && p[k] <= high[k]);
        for i in 0..=40 {
            for j in 0..=(40 - i) {
                let (u, v) = (f64::from(i) / 40.0, f64::from(j) / 40.0);
                let p = [0, 1, 2].map(|k| vertices[0][k] + u * (vertices[1][k] - vertices[0][k]) + v * (vertices[2][k] - vertices[0][k]));
                assert!(pieces.iter().any(|piece| inside(p, piece)), "{p:?} in no piece");
            }
        }
        let total: f64 = pieces.iter().map(area).sum();
        assert!(total < area(&whole) / 8.0, "{total} against {}", area(&whole));
    }

    #[test]
    fn too_little_storage_splits_nothing_and_enough_keeps_every_object() {
        let unit = ([0.0; 3], [1.0; 3]);
        let (mut references, mut owners) = ([unit; 3], [0; 3]);
        assert_eq!(split(4, &|_| unit, &|_| None, &mut references, &mut owners), 0);
        assert_eq!(split(3, &|_| unit, &|_| Some([[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 1.0]]), &mut references, &mut owners), 3);
        assert_eq!(owners, [0, 1, 2]);
    }
}
