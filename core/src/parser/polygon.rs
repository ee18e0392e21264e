//! Splitting a planar polygon into triangles (ear clipping), for NFF's `p` and `pp`: any vertex
//! count, convex or concave, either winding. For a simple polygon (no edge crosses another,
//! as every SPD polygon) the triangles cover exactly its even-odd inside. Repeated and
//! collinear vertices and zero-area spikes add no triangle. A polygon whose edges cross, where
//! no ear remains, has its rest split as a fan (docs/nff.md says so).

/// The most vertices one polygon may have here (the scratch lists live on the stack).
pub const MAX_POLYGON_VERTICES: usize = 1024;

type Point2 = [f64; 2];

/// Twice the signed area of (a, b, c): positive when they turn anticlockwise.
fn orientation(a: Point2, b: Point2, c: Point2) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether `p` lies inside or on the anticlockwise triangle (a, b, c).
fn in_triangle(p: Point2, a: Point2, b: Point2, c: Point2) -> bool {
    orientation(a, b, p) >= 0.0 && orientation(b, c, p) >= 0.0 && orientation(c, a, p) >= 0.0
}

/// The polygon's normal by Newell's method (its length twice the area): robust for concave
/// polygons and collinear vertices.
pub fn newell_normal(points: &[[f64; 3]]) -> [f64; 3] {
    let mut normal = [0.0; 3];
    for (index, current) in points.iter().enumerate() {
        let next = points.get(index + 1).or(points.first()).copied().unwrap_or(*current);
        normal[0] += (current[1] - next[1]) * (current[2] + next[2]);
        normal[1] += (current[2] - next[2]) * (current[0] + next[0]);
        normal[2] += (current[0] - next[0]) * (current[1] + next[1]);
    }
    normal
}

/// Calls `emit` with the vertex indices of each triangle of the polygon `points` (3-D points
/// on one plane). Nothing is emitted for a polygon of no area. `points.len()` must be at most
/// [`MAX_POLYGON_VERTICES`] (more are ignored).
pub fn triangulate<E>(points: &[[f64; 3]], mut emit: impl FnMut([usize; 3]) -> Result<(), E>) -> Result<(), E> {
    let points = points.get(..MAX_POLYGON_VERTICES).unwrap_or(points);
    let normal = newell_normal(points);
    // Project along the normal's largest component, keeping the other two in cyclic order, so
    // a polygon anticlockwise about its normal stays anticlockwise.
    let axis = if normal[0].abs() >= normal[1].abs() && normal[0].abs() >= normal[2].abs() {
        0
    } else if normal[1].abs() >= normal[2].abs() {
        1
    } else {
        2
    };
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let sign = if normal[axis] < 0.0 { -1.0 } else { 1.0 };
    if !(normal[axis] != 0.0 && normal[axis].is_finite()) {
        return Ok(());
    }
    let mut flat: heapless::Vec<Point2, MAX_POLYGON_VERTICES> = heapless::Vec::new();
    for point in points {
        // The sign flips one axis so that every polygon turns anticlockwise in the plane.
        let _ = flat.push([point[u] * sign, point[v]]);
    }
    let at = |index: u16| flat.get(usize::from(index)).copied().unwrap_or([0.0; 2]);
    let mut remaining: heapless::Vec<u16, MAX_POLYGON_VERTICES> = (0..flat.len() as u16).collect();
    // Repeated, straight and folded-back vertices first: they add no area, only triangles.
    loop {
        let before = remaining.len();
        let mut index = 0;
        while remaining.len() >= 3 && index < remaining.len() {
            let count = remaining.len();
            let [a, b, c] = [(index + count - 1) % count, index, (index + 1) % count].map(|k| remaining.get(k).copied().unwrap_or(0));
            if orientation(at(a), at(b), at(c)) == 0.0 {
                remaining.remove(index);
            } else {
                index += 1;
            }
        }
        // A removal may leave the vertex before it straight: again until none is.
        if remaining.len() == before {
            break;
        }
    }
    while remaining.len() > 3 {
        let count = remaining.len();
        // The ear to clip: of all the polygon's ears, the one whose new edge (its diagonal) is
        // shortest, so that the triangles stay compact (a fan of slivers across a gear's face
        // would give every one a box across the face, which the shadow rays' hierarchy cannot
        // tell apart). A straight or folded-back vertex is dropped at once.
        let mut best: Option<(f64, usize, [u16; 3])> = None;
        let mut straight = None;
        for middle in 0..count {
            let [a, b, c] = [(middle + count - 1) % count, middle, (middle + 1) % count].map(|k| remaining.get(k).copied().unwrap_or(0));
            let (pa, pb, pc) = (at(a), at(b), at(c));
            let turn = orientation(pa, pb, pc);
            if turn == 0.0 {
                straight = Some(middle);
                break;
            }
            if turn < 0.0 {
                continue;
            }
            // An ear: no other vertex in it (vertices at its corners' places, where a polygon
            // touches itself, do not count).
            let diagonal = (pc[0] - pa[0]) * (pc[0] - pa[0]) + (pc[1] - pa[1]) * (pc[1] - pa[1]);
            if best.is_some_and(|(shortest, _, _)| shortest <= diagonal) {
                continue;
            }
            let ear = !remaining.iter().any(|&k| {
                let p = at(k);
                k != a && k != b && k != c && p != pa && p != pb && p != pc && in_triangle(p, pa, pb, pc)
            });
            if ear {
                best = Some((diagonal, middle, [a, b, c]));
            }
        }
        let clipped = match (straight, best) {
            (Some(middle), _) => {
                remaining.remove(middle);
                true
            }
            (None, Some((_, middle, corners))) => {
                emit(corners.map(usize::from))?;
                remaining.remove(middle);
                true
            }
            (None, None) => false,
        };
        if !clipped {
            // No ear: the edges cross. Fan the rest.
            let first = remaining.first().copied().unwrap_or(0);
            for pair in remaining.windows(2).skip(1) {
                if let [b, c] = *pair {
                    emit([first, b, c].map(usize::from))?;
                }
            }
            return Ok(());
        }
    }
    if let [a, b, c] = remaining[..] {
        if orientation(at(a), at(b), at(c)) > 0.0 {
            emit([a, b, c].map(usize::from))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;

    fn triangles(points: &[[f64; 3]]) -> Vec<[usize; 3]> {
        let mut out = Vec::new();
        triangulate::<()>(points, |t| {
            out.push(t);
            Ok(())
        })
        .unwrap();
        out
    }

    /// Even-odd inside by crossings, in the plane z = 0 (the independent computation).
    fn even_odd(polygon: &[[f64; 3]], p: [f64; 2]) -> bool {
        let mut inside = false;
        for (index, a) in polygon.iter().enumerate() {
            let b = polygon[(index + 1) % polygon.len()];
            if (a[1] > p[1]) != (b[1] > p[1]) {
                let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if p[0] < x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    fn covered(points: &[[f64; 3]], found: &[[usize; 3]], p: [f64; 2]) -> usize {
        let flat = |k: usize| [points[k][0], points[k][1]];
        found
            .iter()
            .filter(|[a, b, c]| {
                let (a, b, c) = (flat(*a), flat(*b), flat(*c));
                let o = orientation(a, b, c).signum();
                o * orientation(a, b, p) > 0.0 && o * orientation(b, c, p) > 0.0 && o * orientation(c, a, p) > 0.0
            })
            .count()
    }

    /// Sample points over the polygon's box: each inside by the even-odd rule lies in exactly one
    /// triangle, each outside in none (points within 1e-9 of an edge skipped).
    fn check(name: &str, points: &[[f64; 3]]) {
        let found = triangles(points);
        let low = [0, 1].map(|k| points.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min));
        let high = [0, 1].map(|k| points.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max));
        let mut insides = 0;
        for i in 0..97 {
            for j in 0..89 {
                let p = [low[0] + (high[0] - low[0]) * (i as f64 + 0.37) / 97.0, low[1] + (high[1] - low[1]) * (j as f64 + 0.61) / 89.0];
                let inside = even_odd(points, p);
                let count = covered(points, &found, p);
                assert_eq!(count, usize::from(inside), "{name}: at {p:?} inside {inside}, {count} triangles: {found:?}");
                insides += usize::from(inside);
            }
        }
        assert!(insides > 0, "{name}");
    }

    fn reversed(points: &[[f64; 3]]) -> Vec<[f64; 3]> {
        points.iter().rev().copied().collect()
    }

    #[test]
    fn concave_convex_collinear_and_repeated_vertices_in_either_order() {
        let square = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [0.0, 2.0, 0.0]];
        let arrow = [[0.0, 0.0, 0.0], [4.0, 2.0, 0.0], [0.0, 4.0, 0.0], [1.5, 2.0, 0.0]];
        // A comb: a concave polygon of 3 teeth, as a gear's outline is.
        let comb = [[0.0, 0.0, 0.0], [7.0, 0.0, 0.0], [7.0, 3.0, 0.0], [6.0, 3.0, 0.0], [6.0, 1.0, 0.0], [4.0, 1.0, 0.0], [4.0, 3.0, 0.0], [3.0, 3.0, 0.0], [3.0, 1.0, 0.0], [1.0, 1.0, 0.0], [1.0, 3.0, 0.0], [0.0, 3.0, 0.0]];
        let collinear = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [2.0, 2.0, 0.0], [1.0, 2.0, 0.0], [0.0, 2.0, 0.0], [0.0, 1.0, 0.0]];
        let mut star = Vec::new();
        for k in 0..40 {
            let angle = k as f64 * core::f64::consts::PI / 20.0;
            let radius = if k % 2 == 0 { 3.0 } else { 1.0 };
            star.push([radius * angle.cos(), radius * angle.sin(), 0.0]);
        }
        for (name, polygon) in [("square", &square[..]), ("arrow", &arrow[..]), ("comb", &comb[..]), ("collinear", &collinear[..]), ("star", &star[..])] {
            check(name, polygon);
            check(name, &reversed(polygon));
        }
        assert_eq!(triangles(&square).len(), 2);
        assert_eq!(triangles(&collinear).len(), 2, "collinear and repeated vertices add no triangle");
    }

    #[test]
    fn degenerate_polygons_give_no_triangles() {
        assert!(triangles(&[[0.0; 3], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]]).is_empty(), "collinear");
        assert!(triangles(&[[1.0; 3], [1.0; 3], [1.0; 3], [1.0; 3]]).is_empty(), "one point");
        assert!(triangles(&[[0.0; 3], [1.0, 0.0, 0.0]]).is_empty(), "two points");
    }

    #[test]
    fn a_polygon_in_any_plane_keeps_its_shape() {
        // The comb tilted out of z = 0: its triangles' areas add up to the comb's (15).
        let comb = [[0.0, 0.0], [7.0, 0.0], [7.0, 3.0], [6.0, 3.0], [6.0, 1.0], [4.0, 1.0], [4.0, 3.0], [3.0, 3.0], [3.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]];
        let tilted: Vec<[f64; 3]> = comb.iter().map(|[x, y]| [0.6 * x, 0.8 * x + 0.3 * y, -0.9 * y]).collect();
        let scale = newell_normal(&tilted).iter().map(|c| c * c).sum::<f64>().sqrt() / 2.0 / 15.0;
        let area: f64 = triangles(&tilted)
            .iter()
            .map(|t| newell_normal(&t.map(|k| tilted[k])).iter().map(|c| c * c).sum::<f64>().sqrt() / 2.0)
            .sum();
        assert!((area / scale - 15.0).abs() < 1e-9, "{area} {scale}");
    }
}
