//! `projectvolume` (digest §8.3): world points onto the view plane along the primary rays, then
//! to continuous image coordinates (column from the left, row from the top), in `f64`.
//!
//! Unlike the thesis, a volume with a vertex at or behind the eye plane (perspective, B16) is
//! clipped there: only its part that a primary ray can reach is projected ([`Screen::clip_depth`]).
//! Any volume when the parallel direction is parallel to the view plane (B17), or one that
//! cannot be clipped (the eye inside it), has no usable projection: callers then treat it as
//! covering the whole screen.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::bounding_volume::{ObjectGeometry, View, MAX_POINTS};
use crate::camera::Camera;
use crate::number::Number;
use crate::model::Primitive;

/// The camera's mapping in `f64`, read back from the number type's own values so that it is
/// the mapping the primary rays actually use.
#[derive(Clone, Copy, Debug)]
pub struct Screen {
    pub width: u16,
    pub height: u16,
    /// View-plane x of column 0 and y of the bottom row, and the spacing between samples
    /// (0 for a single column or row).
    x0: f64,
    y0: f64,
    spacing_x: f64,
    spacing_y: f64,
    pub view_plane: f64,
    pub view: View,
}

/// A projected object: the convex hull of its silhouette points in image coordinates.
#[derive(Clone, Copy, Debug)]
#[allow(clippy::large_enum_variant)]
pub enum Projected {
    Points(Polygon),
    /// No usable projection: may cover any pixel.
    Whole,
    /// No primary ray can reach it.
    Invisible,
}

/// Margin in pixels added around every projected shape: covers the rounding of the number
/// type's rays and intersections (a hit is never found more than a small fraction of a pixel
/// outside the exact silhouette).
pub const MARGIN: f64 = 0.1;

/// Pixels by which the eye-plane clip widens the window's frustum: a point beyond it cannot be
/// reached by a primary ray, whatever the rounding of rays and projection.
const CLIP_PAD: f64 = 1.0;

/// Largest image coordinate a clipped silhouette may have: beyond it, interpolating along an
/// edge that crosses the screen would lose the margin's precision.
const CLIP_LIMIT: f64 = 1e9;

impl Screen {
    /// Every byte zero: the value before [`crate::optimize::Acceleration::rebuild`].
    pub const UNSET: Self = Self {
        width: 0,
        height: 0,
        x0: 0.0,
        y0: 0.0,
        spacing_x: 0.0,
        spacing_y: 0.0,
        view_plane: 0.0,
        view: View::Parallel { direction: [0.0; 3] },
    };

    /// Only the size (the firmware, without the `f64-silhouettes` feature: nothing projects).
    pub const fn sized(width: u16, height: u16) -> Self {
        Self { width, height, ..Self::UNSET }
    }

    pub fn new<N: Number>(camera: &Camera<N>) -> Self {
        let (width, height) = (camera.width(), camera.height());
        let first = camera.view_plane_point(camera.pixel(0, height - 1)).to_f64();
        let last = camera.view_plane_point(camera.pixel(width - 1, 0)).to_f64();
        let spacing = |from: f64, to: f64, pixels: u16| if pixels > 1 { (to - from) / f64::from(pixels - 1) } else { 0.0 };
        let view = match (camera.parallel_direction(), camera.eye()) {
            (Some(direction), _) => View::Parallel { direction: direction.to_f64() },
            (None, Some(eye)) => View::Perspective { eye: eye.to_f64() },
            (None, None) => View::Perspective { eye: [0.0; 3] },
        };
        Self {
            width,
            height,
            x0: first[0],
            y0: first[1],
            spacing_x: spacing(first[0], last[0], width),
            spacing_y: spacing(first[1], last[1], height),
            view_plane: first[2],
            view,
        }
    }

    /// The view-plane point a primary ray through world point `p` starts from (parallel) or
    /// passes through (perspective); `None` when there is none in front of the eye.
    pub fn project(&self, p: [f64; 3]) -> Option<[f64; 2]> {
        match self.view {
            View::Parallel { direction: d } => {
                if d[2].abs() < 1e-9 {
                    return None;
                }
                let t = (p[2] - self.view_plane) / d[2];
                Some([p[0] - t * d[0], p[1] - t * d[1]])
            }
            View::Perspective { eye: e } => {
                let span = self.view_plane - e[2];
                if span == 0.0 {
                    return None;
                }
                let w = (p[2] - e[2]) / span;
                if !(w > 1e-9) {
                    return None;
                }
                Some([e[0] + (p[0] - e[0]) / w, e[1] + (p[1] - e[1]) / w])
            }
        }
    }

    /// Continuous image (column, row from the top) to view-plane (x, y).
    pub fn to_view_plane(&self, column: f64, row: f64) -> [f64; 2] {
        [self.x0 + column * self.spacing_x, self.y0 + (f64::from(self.height - 1) - row) * self.spacing_y]
    }

    /// View-plane (x, y) to continuous image (column, row from the top).
    pub fn to_image(&self, point: [f64; 2]) -> [f64; 2] {
        let column = if self.spacing_x > 0.0 { (point[0] - self.x0) / self.spacing_x } else { 0.0 };
        let row = if self.spacing_y > 0.0 { f64::from(self.height - 1) - (point[1] - self.y0) / self.spacing_y } else { 0.0 };
        [column, row]
    }

    /// The object's silhouette in image coordinates. A silhouette point at or behind the eye
    /// plane (digest B16) clips the hull at the eye (`Screen::project_clipped`); `Whole` when
    /// that fails or for rays along the view plane (B17). An object whose bounding volume lies
    /// wholly behind the rays' origins (every vertex behind the eye plane, or behind the
    /// parallel view plane, by a margin) is `Invisible`: no primary ray can reach it.
    /// With `tight` off, the thesis's 8 volume vertices are projected instead.
    pub fn project_object(&self, geometry: &ObjectGeometry, tight: bool) -> Projected {
        let volume = geometry.volume();
        if volume.iter().all(|p| self.behind(*p)) {
            return Projected::Invisible;
        }
        let mut world = [[0.0; 3]; MAX_POINTS];
        let count = if tight && super::build_options::TABLES {
            let Some(count) = geometry.silhouette_points(&self.view, &mut world) else { return Projected::Whole };
            count
        } else {
            world[..8].copy_from_slice(&volume);
            8
        };
        let mut image = [[0.0; 2]; MAX_POINTS];
        for (vertex, image) in world[..count].iter().zip(image.iter_mut()) {
            let Some(point) = self.project(*vertex) else {
                // A sphere's rim bounds it only as seen through the rim; its box contains it.
                let hull = if tight && geometry.primitive == Primitive::Sphere { &volume[..] } else { &world[..count] };
                return self.project_clipped(geometry, hull);
            };
            *image = self.to_image(point);
            if !(image[0].is_finite() && image[1].is_finite()) {
                return Projected::Whole;
            }
        }
        Projected::Points(Polygon::hull(&mut image[..count]))
    }

    /// A depth `ε > 0` (in units where the view plane is at 1, measured from the eye along z)
    /// such that no primary ray can reach a point of the hull of `points` nearer than `ε`, for a
    /// perspective view; `INFINITY` when no ray can reach the hull at all; `None` when none is
    /// found (the eye may be in the hull). Two ways, the larger wins:
    /// - per face of the window's frustum (widened by `CLIP_PAD` pixels): the hull's points on
    ///   the inner side of the face's plane form the hull clipped by it, the hull of the points
    ///   inside and of the crossings of every segment between two points (the hull contains the
    ///   segment, so its crossing); if they all lie in front of the eye, the nearest is such an
    ///   `ε` (anything nearer is beyond that face); if none does, nothing is visible;
    /// - the eye's distance to the object's volume (a lower bound), over the longest distance
    ///   from the eye to the view plane through the window.
    ///
    /// `None` too when the eye is within 0.1 % of the object's size and distance of its volume:
    /// there a ray's rounding may outweigh the pad.
    pub fn clip_depth(&self, points: &[[f64; 3]], geometry: &ObjectGeometry) -> Option<f64> {
        let View::Perspective { eye: e } = self.view else { return None };
        let span = self.view_plane - e[2];
        if span == 0.0 || self.spacing_x == 0.0 || self.spacing_y == 0.0 {
            return None;
        }
        let distance = geometry.distance_lower_bound(e);
        let (centre, radius) = geometry.bounding_sphere();
        let offset = [0, 1, 2].map(|k| centre[k] - e[k]);
        if !(distance >= 1e-3 * (libm::sqrt(offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2]) + radius)) {
            return None;
        }
        let w = |p: [f64; 3]| (p[2] - e[2]) / span;
        // The widened window's edges on the view plane, relative to the eye.
        let edges = |start: f64, spacing: f64, count: u16, eye: f64| {
            let end = start + f64::from(count - 1) * spacing;
            let pad = CLIP_PAD * spacing.abs();
            (start.min(end) - pad - eye, start.max(end) + pad - eye)
        };
        let (x_low, x_high) = edges(self.x0, self.spacing_x, self.width, e[0]);
        let (y_low, y_high) = edges(self.y0, self.spacing_y, self.height, e[1]);
        // Inside face (axis, sign, edge) ⟺ sign·((p − e)[axis] − edge·w(p)) ≥ 0.
        let faces = [(0, 1.0, x_low), (0, -1.0, x_high), (1, 1.0, y_low), (1, -1.0, y_high)];
        let reach = {
            let (x, y) = (x_low.abs().max(x_high.abs()), y_low.abs().max(y_high.abs()));
            libm::sqrt(span * span + x * x + y * y)
        };
        let mut depth = distance / reach * (1.0 - 1e-6);
        for (axis, sign, edge) in faces {
            let g = |p: [f64; 3]| sign * ((p[axis] - e[axis]) - edge * w(p));
            let (mut nearest, mut behind) = (f64::INFINITY, false);
            let mut consider = |depth: f64| {
                if depth > 0.0 {
                    nearest = nearest.min(depth);
                } else {
                    behind = true;
                }
            };
            for (i, &a) in points.iter().enumerate() {
                let (ga, wa) = (g(a), w(a));
                if !(ga.is_finite() && wa.is_finite()) {
                    return None;
                }
                if ga >= 0.0 {
                    consider(wa);
                }
                for &b in &points[i + 1..] {
                    let gb = g(b);
                    if (ga < 0.0 && gb > 0.0) || (ga > 0.0 && gb < 0.0) {
                        consider(wa + ga / (ga - gb) * (w(b) - wa));
                    }
                }
            }
            if nearest == f64::INFINITY {
                // Nothing in front of the eye is inside this face.
                return Some(f64::INFINITY);
            }
            if !behind {
                depth = depth.max(nearest);
            }
        }
        (depth > 0.0).then_some(depth)
    }

    /// The silhouette of the part of the hull of `points` (which contains the object) that a
    /// primary ray can reach (B16): the hull clipped to depth ≥ ε/2 ([`Screen::clip_depth`]),
    /// the points in front and the crossings of every segment between a point in front and one
    /// behind, projected. Within the window it holds every point of the object a ray can reach
    /// (and is the hull's own projection when ε came from a frustum face); the part cut off
    /// lies beyond the widened window or nearer than the object. Out of line, so that the
    /// scratch hull costs stack only for objects that reach the eye plane.
    #[inline(never)]
    fn project_clipped(&self, geometry: &ObjectGeometry, points: &[[f64; 3]]) -> Projected {
        let View::Perspective { eye: e } = self.view else { return Projected::Whole };
        let Some(depth) = self.clip_depth(points, geometry) else { return Projected::Whole };
        if depth == f64::INFINITY {
            return Projected::Invisible;
        }
        let near = depth / 2.0;
        let span = self.view_plane - e[2];
        let w = |p: [f64; 3]| (p[2] - e[2]) / span;
        let mut scratch = Scratch { points: [[0.0; 2]; 2 * MAX_POINTS], count: 0 };
        let mut add = |p: [f64; 3], w: f64| {
            let image = self.to_image([e[0] + (p[0] - e[0]) / w, e[1] + (p[1] - e[1]) / w]);
            image.iter().all(|c| c.abs() <= CLIP_LIMIT) && scratch.push(image)
        };
        for (i, &a) in points.iter().enumerate() {
            let wa = w(a);
            if wa >= near && !add(a, wa) {
                return Projected::Whole;
            }
            for &b in &points[i + 1..] {
                let wb = w(b);
                if (wa < near) != (wb < near) {
                    let s = (near - wa) / (wb - wa);
                    if !add(core::array::from_fn(|k| a[k] + s * (b[k] - a[k])), near) {
                        return Projected::Whole;
                    }
                }
            }
        }
        match scratch.hull() {
            0 => Projected::Invisible,
            count if count <= MAX_POINTS => {
                let mut polygon = Polygon { points: [[0.0; 2]; MAX_POINTS], count };
                polygon.points[..count].copy_from_slice(&scratch.points[..count]);
                Projected::Points(polygon)
            }
            _ => Projected::Whole,
        }
    }

    /// Whether `p` lies clearly behind where every primary ray starts (so t < 0 for it).
    fn behind(&self, p: [f64; 3]) -> bool {
        let margin = 1e-6 * (1.0 + p[2].abs() + self.view_plane.abs());
        match self.view {
            View::Parallel { direction: d } => {
                // t = (p.z − D)/d.z < 0.
                (d[2] > 1e-9 && p[2] < self.view_plane - margin) || (d[2] < -1e-9 && p[2] > self.view_plane + margin)
            }
            View::Perspective { eye: e } => {
                let span = self.view_plane - e[2];
                (span > 0.0 && p[2] < e[2] - margin) || (span < 0.0 && p[2] > e[2] + margin)
            }
        }
    }

    /// Inclusive integer range of columns (or rows) within `[low − MARGIN, high + MARGIN]`,
    /// clipped to `0..count`; `None` when empty.
    pub fn pixel_range(low: f64, high: f64, count: u16) -> Option<(u16, u16)> {
        let first = libm::ceil(low - MARGIN).max(0.0);
        let last = libm::floor(high + MARGIN).min(f64::from(count) - 1.0);
        (first <= last).then_some((first as u16, last as u16))
    }
}

/// Image points whose hull is kept in place as they come (the eye-plane clip's crossings).
struct Scratch {
    points: [[f64; 2]; 2 * MAX_POINTS],
    count: usize,
}

impl Scratch {
    /// Adds a point, first reducing the points to their hull when full; false when the hull
    /// alone fills the scratch, or a point is not finite.
    fn push(&mut self, point: [f64; 2]) -> bool {
        if !(point[0].is_finite() && point[1].is_finite()) {
            return false;
        }
        if self.count == self.points.len() && self.hull() == self.points.len() {
            return false;
        }
        self.points[self.count] = point;
        self.count += 1;
        true
    }

    /// Reduces the points to their convex hull, in order, counter-clockwise from the least
    /// (x, y) like [`Polygon::hull`]; returns the count. Andrew's monotone chain in place: the
    /// points below the line from the least to the greatest point (which alone can be on the
    /// lower chain) first, those above after, each chain's stack never overtaking its input.
    fn hull(&mut self) -> usize {
        let n = self.count;
        let p = &mut self.points[..n];
        let less = |a: [f64; 2], b: [f64; 2]| (a[0], a[1]) < (b[0], b[1]);
        let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
        if n < 2 {
            return n;
        }
        // The least point first, the greatest last.
        let least = (1..n).fold(0, |best, i| if less(p[i], p[best]) { i } else { best });
        p.swap(0, least);
        let greatest = (1..n).fold(1, |best, i| if less(p[best], p[i]) { i } else { best });
        p.swap(n - 1, greatest);
        let (left, right) = (p[0], p[n - 1]);
        if !less(left, right) {
            self.count = 1;
            return 1;
        }
        // [left, below…, right, above…].
        let mut m = 1;
        for i in 1..n - 1 {
            if cross(left, right, p[i]) <= 0.0 {
                p.swap(i, m);
                m += 1;
            }
        }
        p.swap(m, n - 1);
        let sort = |points: &mut [[f64; 2]], ascending: bool| {
            for i in 1..points.len() {
                let mut j = i;
                while j > 0 && less(points[j], points[j - 1]) == ascending && points[j] != points[j - 1] {
                    points.swap(j, j - 1);
                    j -= 1;
                }
            }
        };
        sort(&mut p[1..m], true);
        sort(&mut p[m + 1..], false);
        let mut k = 0;
        for i in 0..=m {
            while k >= 2 && cross(p[k - 2], p[k - 1], p[i]) <= 0.0 {
                k -= 1;
            }
            p[k] = p[i];
            k += 1;
        }
        let base = k - 1;
        for i in (m + 1..n).chain(core::iter::once(0)) {
            while k >= base + 2 && cross(p[k - 2], p[k - 1], p[i]) <= 0.0 {
                k -= 1;
            }
            if i != 0 {
                p[k] = p[i];
                k += 1;
            }
        }
        self.count = k;
        k
    }
}

/// A convex polygon (counter-clockwise in image coordinates), at most `MAX_POINTS` vertices.
#[derive(Clone, Copy, Debug)]
pub struct Polygon {
    pub points: [[f64; 2]; MAX_POINTS],
    pub count: usize,
}

impl Polygon {
    /// The convex hull of `points` (Andrew's monotone chain; sorts `points` in place).
    pub fn hull(points: &mut [[f64; 2]]) -> Self {
        let n = points.len().min(MAX_POINTS);
        let points = &mut points[..n];
        // Insertion sort by (x, y): at most 32 points.
        for i in 1..n {
            let mut j = i;
            while j > 0 && (points[j][0], points[j][1]) < (points[j - 1][0], points[j - 1][1]) {
                points.swap(j, j - 1);
                j -= 1;
            }
        }
        let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
        let mut hull = [[0.0; 2]; MAX_POINTS];
        let mut chain = [[0.0; 2]; 2 * MAX_POINTS];
        let mut k = 0usize;
        for &p in points.iter() {
            while k >= 2 && cross(chain[k - 2], chain[k - 1], p) <= 0.0 {
                k -= 1;
            }
            chain[k] = p;
            k += 1;
        }
        let lower = k + 1;
        for &p in points.iter().rev().skip(1) {
            while k >= lower && cross(chain[k - 2], chain[k - 1], p) <= 0.0 {
                k -= 1;
            }
            chain[k] = p;
            k += 1;
        }
        // The last point repeats the first (for n >= 2).
        let count = if n >= 2 { (k - 1).min(MAX_POINTS) } else { n };
        hull[..count].copy_from_slice(&chain[..count]);
        Self { points: hull, count }
    }

    pub fn vertices(&self) -> &[[f64; 2]] {
        &self.points[..self.count]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{AffineTransform, Matrix4};
    use crate::model::{Projection, Viewport, Window};

    struct XorShift(u64);

    impl XorShift {
        fn unit(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        fn range(&mut self, low: f64, high: f64) -> f64 {
            low + (high - low) * self.unit()
        }
    }

    fn screen(eye: [f64; 3]) -> Screen {
        let viewport = Viewport { x1: 0, x2: 39, y1: 0, y2: 29 };
        let window = Window { x1: -4.0, x2: 4.0, y1: -3.0, y2: 3.0 };
        Screen::new(&Camera::<f64>::new(viewport, window, -5.0, Projection::Perspective { eye }).unwrap())
    }

    fn geometry(primitive: Primitive, world_from_object: &Matrix4) -> ObjectGeometry {
        ObjectGeometry::new(primitive, &AffineTransform::<f64>::from_matrix(&world_from_object.affine_inverse().unwrap())).unwrap()
    }

    /// A point of the unit primitive, uniformly in its box and rejected until inside.
    fn sample(rng: &mut XorShift, primitive: Primitive) -> [f64; 3] {
        loop {
            let (x, y, z) = (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
            let inside = match primitive {
                Primitive::Cube | Primitive::Solid(_) => return [x.abs(), y.abs(), z.abs()],
                Primitive::Sphere => x * x + y * y + z * z <= 1.0,
                Primitive::Cylinder => x * x + y * y <= 1.0,
                Primitive::Cone => x * x + y * y <= z * z,
                Primitive::Frustum(taper) => {
                    let radius = taper.to_f64() + (1.0 - taper.to_f64()) * z.abs();
                    x * x + y * y <= radius * radius
                }
                #[cfg(feature = "triangle")]
                Primitive::Patch(_) => return [x.abs().min(0.5), y.abs().min(0.5), 0.0],
                Primitive::Disc => {
                    if x * x + y * y <= 1.0 {
                        return [x, y, 0.0];
                    }
                    false
                }
                Primitive::Triangle => {
                    let (u, v) = (x.abs(), y.abs());
                    if u + v <= 1.0 {
                        return [u, v, 0.0];
                    }
                    false
                }
                Primitive::Torus(tube) => {
                    let (r, reach) = (tube.to_f64(), 1.0 + tube.to_f64());
                    let (x, y, z) = (x * reach, y * reach, z * r);
                    if ((x * x + y * y).sqrt() - 1.0).powi(2) + z * z <= r * r {
                        return [x, y, z];
                    }
                    false
                }
            };
            if inside {
                return [x, y, if primitive == Primitive::Sphere { z } else { z.abs() }];
            }
        }
    }

    fn inside(polygon: &Polygon, p: [f64; 2]) -> bool {
        let v = polygon.vertices();
        (0..v.len()).all(|i| {
            let (a, b) = (v[i], v[(i + 1) % v.len()]);
            let length = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
            (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= -1e-7 * length.max(1.0)
        })
    }

    /// Objects through the eye plane (B16): every point of the object that a primary ray can
    /// reach (in front of the eye, projecting into the window) projects into the clipped
    /// silhouette, in both tunings; and most such objects get a silhouette, not the whole screen.
    #[test]
    fn clipped_silhouettes_contain_every_visible_point() {
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D);
        let (mut clipped, mut cases) = (0, 0);
        for case in 0..400 {
            let eye = [rng.range(-2.0, 2.0), rng.range(-2.0, 2.0), rng.range(0.0, 10.0)];
            let screen = screen(eye);
            let primitive = Primitive::ALL[case % Primitive::ALL.len()];
            let mut m = Matrix4::IDENTITY;
            m.translate([-0.5, -0.5, -0.5]);
            m.scale([rng.range(0.5, 20.0), rng.range(0.5, 20.0), rng.range(0.5, 20.0)]);
            for axis in 0..3 {
                m.rotate(axis, rng.range(-180.0, 180.0));
            }
            // Around the eye plane, beside the eye.
            m.translate([eye[0] + rng.range(-12.0, 12.0), eye[1] + rng.range(-12.0, 12.0), eye[2] + rng.range(-3.0, 3.0)]);
            let geometry = geometry(primitive, &m);
            let span = screen.view_plane - eye[2];
            let reaches = geometry.volume().iter().any(|p| (p[2] - eye[2]) / span <= 1e-9);
            for tight in [false, true] {
                let projected = screen.project_object(&geometry, tight);
                if reaches {
                    cases += 1;
                    clipped += usize::from(!matches!(projected, Projected::Whole));
                }
                for _ in 0..2000 {
                    let p = m.transform_point(sample(&mut rng, primitive));
                    let Some(point) = screen.project(p) else { continue };
                    let image = screen.to_image(point);
                    if image[0] < -0.5 || image[0] > 39.5 || image[1] < -0.5 || image[1] > 29.5 {
                        continue;
                    }
                    match &projected {
                        Projected::Whole => {}
                        Projected::Invisible => panic!("case {case} tight {tight}: {p:?} visible at {image:?} of an invisible object"),
                        Projected::Points(polygon) => {
                            assert!(inside(polygon, image), "case {case} tight {tight}: {p:?} at {image:?} outside {polygon:?}")
                        }
                    }
                }
            }
        }
        extern crate std;
        std::println!("{clipped} of {cases} clipped");
        assert!(clipped * 2 > cases, "only {clipped} of {cases} objects reaching the eye plane were clipped");
    }

    /// A ground under the eye, reaching far behind it: its silhouette is the screen below the
    /// horizon, not the whole screen.
    #[test]
    fn a_ground_behind_the_eye_covers_only_the_screen_below_the_horizon() {
        let screen = screen([0.0, 0.0, 0.0]);
        let mut m = Matrix4::IDENTITY;
        m.scale([200.0, 0.1, 200.0]);
        m.translate([-100.0, -2.1, -100.0]);
        // Looking along −z, the ground's top at y = −2: its far edge (z = −100) is at
        // y = −0.1 on the view plane, row 29 − 2.9·29/6.
        for tight in [false, true] {
            let Projected::Points(polygon) = screen.project_object(&geometry(Primitive::Cube, &m), tight) else { panic!("not clipped") };
            let top = polygon.vertices().iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
            assert!((top - (29.0 - 2.9 * 29.0 / 6.0)).abs() < 1e-9, "{polygon:?}");
        }
    }
}

#[cfg(test)]
mod hull_tests {
    use super::*;

    #[test]
    fn the_scratch_hull_is_the_polygon_hull() {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut unit = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for case in 0..2000 {
            let n = 1 + (unit() * (MAX_POINTS - 1) as f64) as usize;
            let scale = if case % 3 == 0 { 1e6 } else { 10.0 };
            let mut scratch = Scratch { points: [[0.0; 2]; 2 * MAX_POINTS], count: 0 };
            let mut points = [[0.0; 2]; MAX_POINTS];
            for point in points.iter_mut().take(n) {
                *point = [(unit() - 0.5) * scale, (unit() - 0.5) * scale * unit()];
                assert!(scratch.push(*point));
            }
            let expected = Polygon::hull(&mut points[..n]);
            let count = scratch.hull();
            assert_eq!(&scratch.points[..count], expected.vertices(), "case {case}");
        }
        // Many nearly collinear points (on the edges of a large polygon, as the eye-plane
        // clip's crossings are), duplicates, up to the scratch's size: every point in the hull.
        for case in 0..2000 {
            let mut scratch = Scratch { points: [[0.0; 2]; 2 * MAX_POINTS], count: 0 };
            let scale = if case % 2 == 0 { 1e3 } else { 1.0 };
            let corners: [[f64; 2]; 5] = core::array::from_fn(|_| [(unit() - 0.5) * scale, (unit() - 0.5) * scale]);
            let n = 1 + (unit() * (2 * MAX_POINTS - 1) as f64) as usize;
            for _ in 0..n {
                let (a, b) = (corners[(unit() * 5.0) as usize], corners[(unit() * 5.0) as usize]);
                let s = if unit() < 0.2 { 0.0 } else { unit() };
                assert!(scratch.push([a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])]));
            }
            let all = scratch.points;
            let count = scratch.hull();
            let hull = &scratch.points[..count];
            for point in &all[..n] {
                let inside = (0..count).all(|i| {
                    let (a, b) = (hull[i], hull[(i + 1) % count]);
                    let length = libm::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]));
                    count < 3 || (b[0] - a[0]) * (point[1] - a[1]) - (b[1] - a[1]) * (point[0] - a[0]) >= -1e-9 * scale * length
                });
                assert!(inside, "case {case}: {point:?} outside {hull:?}");
            }
            for i in 0..count.saturating_sub(2) {
                assert!(hull[i] != hull[i + 1], "case {case}: repeated vertex");
            }
        }
    }
}
