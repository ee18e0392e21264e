//! `projectvolume` (digest §8.3): world points onto the view plane along the primary rays, then
//! to continuous image coordinates (column from the left, row from the top), in `f64`.
//!
//! Unlike the thesis, a volume with a vertex at or behind the eye plane (perspective, B16), or
//! any volume when the parallel direction is parallel to the view plane (B17), has no usable
//! projection: callers then treat it as covering the whole screen.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::bounding_volume::{ObjectGeometry, MAX_POINTS};
use crate::camera::Camera;
use crate::number::Number;

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

#[derive(Clone, Copy, Debug)]
pub enum View {
    Parallel { direction: [f64; 3] },
    Perspective { eye: [f64; 3] },
}

/// Margin in pixels added around every projected shape: covers the rounding of the number
/// type's rays and intersections (a hit is never found more than a small fraction of a pixel
/// outside the exact silhouette).
pub const MARGIN: f64 = 0.1;

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

    /// The object's silhouette in image coordinates; `Whole` when some silhouette point has no
    /// projection (at or behind the eye: digest B16; rays along the view plane: B17). An object
    /// whose bounding volume lies wholly behind the rays' origins (every vertex behind the eye
    /// plane, or behind the parallel view plane, by a margin) is `Invisible`: no primary ray
    /// can reach it.
    /// With `tight` off, the thesis's 8 volume vertices are projected instead.
    pub fn project_object(&self, geometry: &ObjectGeometry, tight: bool) -> Projected {
        let volume = geometry.volume();
        if volume.iter().all(|p| self.behind(*p)) {
            return Projected::Invisible;
        }
        let mut world = [[0.0; 3]; MAX_POINTS];
        let count = if tight && super::TABLES {
            let Some(count) = geometry.silhouette_points(&self.view, &mut world) else { return Projected::Whole };
            count
        } else {
            world[..8].copy_from_slice(&volume);
            8
        };
        let mut image = [[0.0; 2]; MAX_POINTS];
        for (vertex, image) in world[..count].iter().zip(image.iter_mut()) {
            let Some(point) = self.project(*vertex) else { return Projected::Whole };
            *image = self.to_image(point);
            if !(image[0].is_finite() && image[1].is_finite()) {
                return Projected::Whole;
            }
        }
        Projected::Points(Polygon::hull(&mut image[..count]))
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
