//! The thesis's pixel-to-view-plane mapping (digest §3.1–3.3) and primary rays.
//!
//! Pixel (x, y) in screen coordinates (y up) samples the view plane at
//! `Xw = (x − vx1)·(wx2 − wx1)/(vx2 − vx1) + wx1`, likewise for y: the first and last pixels
//! sample the window's edges exactly. Rays are traced top row first.
//!
//! Unlike the thesis, primary ray directions are normalised, so `t` is a distance in world
//! units; which object a ray hits is unchanged.

use crate::geometry::{Ray, Vector3};
use crate::number::Number;
use crate::model::{Projection, Viewport, Window};

/// Where a pixel is: image coordinates (row 0 at the top) and the thesis's screen coordinates
/// (y up), which the dither and roughness use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelPosition {
    pub column: u16,
    pub row: u16,
    pub screen_x: u16,
    pub screen_y: u16,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum RayOrigin<N> {
    /// Parallel projection: every ray has this unit direction and starts on the view plane.
    Parallel { direction: Vector3<N> },
    /// Perspective: every ray starts at the eye.
    Perspective { eye: Vector3<N> },
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera<N> {
    pub viewport: Viewport,
    /// View-plane coordinates of image column 0 and of the bottom row.
    window_x1: N,
    window_y1: N,
    /// View-plane distance between neighbouring pixel samples.
    spacing_x: N,
    spacing_y: N,
    view_plane: N,
    origin: RayOrigin<N>,
}

impl<N: Number> Camera<N> {
    /// Every byte zero, no camera at all: the value of a scene before it is prepared in place
    /// (`Scene::UNPREPARED`, which then costs only zero-initialised RAM).
    pub const UNSET: Self = Self {
        viewport: Viewport { x1: 0, x2: 0, y1: 0, y2: 0 },
        window_x1: N::ZEROED,
        window_y1: N::ZEROED,
        spacing_x: N::ZEROED,
        spacing_y: N::ZEROED,
        view_plane: N::ZEROED,
        origin: RayOrigin::Parallel { direction: Vector3 { x: N::ZEROED, y: N::ZEROED, z: N::ZEROED } },
    };

    /// `None` when the parallel direction is zero.
    pub fn new(viewport: Viewport, window: Window, view_plane: f64, projection: Projection) -> Option<Self> {
        let spacing = |from: f64, to: f64, pixels: u16| {
            if pixels > 1 { (to - from) / f64::from(pixels - 1) } else { 0.0 }
        };
        // A single column or row samples the middle of the window.
        let start = |from: f64, to: f64, pixels: u16| if pixels > 1 { from } else { (from + to) / 2.0 };
        let origin = match projection {
            Projection::Parallel { direction } => {
                let length = libm::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
                if length == 0.0 || !length.is_finite() {
                    return None;
                }
                RayOrigin::Parallel { direction: Vector3::from_f64(direction.map(|c| c / length)) }
            }
            Projection::Perspective { eye } => RayOrigin::Perspective { eye: Vector3::from_f64(eye) },
        };
        Some(Self {
            viewport,
            window_x1: N::from_f64(start(window.x1, window.x2, viewport.width())),
            window_y1: N::from_f64(start(window.y1, window.y2, viewport.height())),
            spacing_x: N::from_f64(spacing(window.x1, window.x2, viewport.width())),
            spacing_y: N::from_f64(spacing(window.y1, window.y2, viewport.height())),
            view_plane: N::from_f64(view_plane),
            origin,
        })
    }

    pub fn width(&self) -> u16 {
        self.viewport.width()
    }

    pub fn height(&self) -> u16 {
        self.viewport.height()
    }

    pub fn pixel(&self, column: u16, row: u16) -> PixelPosition {
        PixelPosition {
            column,
            row,
            screen_x: self.viewport.x1 + column,
            screen_y: self.viewport.y2 - row,
        }
    }

    /// The point on the view plane that a pixel samples (`generateray`'s Xw, Yw, Zw).
    pub fn view_plane_point(&self, pixel: PixelPosition) -> Vector3<N> {
        let from_bottom = self.viewport.height() - 1 - pixel.row;
        Vector3::new(
            N::from_i32(i32::from(pixel.column)) * self.spacing_x + self.window_x1,
            N::from_i32(i32::from(from_bottom)) * self.spacing_y + self.window_y1,
            self.view_plane,
        )
    }

    /// The primary ray through a pixel, with a unit direction; `None` when a perspective eye
    /// lies exactly on the pixel's sample point.
    #[inline]
    pub fn primary_ray(&self, pixel: PixelPosition) -> Option<Ray<N>> {
        let point = self.view_plane_point(pixel);
        match self.origin {
            RayOrigin::Parallel { direction } => Some(Ray { origin: point, direction }),
            RayOrigin::Perspective { eye } => {
                Some(Ray { origin: eye, direction: (point - eye).normalized()? })
            }
        }
    }

    /// A camera from its parts in the number type (a baked scene: `crate::bake`):
    /// the sample grid as [`Camera::sampling`] gives it, and the eye of a perspective view or
    /// the unit direction of a parallel one.
    pub const fn from_parts(viewport: Viewport, origin: [N; 2], spacing: [N; 2], view_plane: N, eye: Option<Vector3<N>>, direction: Vector3<N>) -> Self {
        let origin_of_rays = match eye {
            Some(eye) => RayOrigin::Perspective { eye },
            None => RayOrigin::Parallel { direction },
        };
        Self {
            viewport,
            window_x1: origin[0],
            window_y1: origin[1],
            spacing_x: spacing[0],
            spacing_y: spacing[1],
            view_plane,
            origin: origin_of_rays,
        }
    }

    /// The view-plane sample grid: (x of column 0, y of the bottom row), the spacing between
    /// neighbouring samples (zero for a single column or row), and the view plane's z.
    pub fn sampling(&self) -> ([N; 2], [N; 2], N) {
        ([self.window_x1, self.window_y1], [self.spacing_x, self.spacing_y], self.view_plane)
    }

    /// The common direction of all rays for a parallel projection, `None` for perspective.
    pub fn parallel_direction(&self) -> Option<Vector3<N>> {
        match self.origin {
            RayOrigin::Parallel { direction } => Some(direction),
            RayOrigin::Perspective { .. } => None,
        }
    }

    /// The eye of a perspective projection.
    pub fn eye(&self) -> Option<Vector3<N>> {
        match self.origin {
            RayOrigin::Perspective { eye } => Some(eye),
            RayOrigin::Parallel { .. } => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corner_pixels_sample_the_window_edges_and_rows_run_top_first() {
        let viewport = Viewport { x1: 10, x2: 14, y1: 0, y2: 4 };
        let window = Window { x1: -2.0, x2: 2.0, y1: -1.0, y2: 1.0 };
        let camera = Camera::<f64>::new(viewport, window, 5.0, Projection::Parallel { direction: [0.0, 0.0, -2.0] }).unwrap();
        let top_left = camera.pixel(0, 0);
        assert_eq!((top_left.screen_x, top_left.screen_y), (10, 4));
        let ray = camera.primary_ray(top_left).unwrap();
        assert_eq!(ray.origin.to_f64(), [-2.0, 1.0, 5.0]);
        assert_eq!(ray.direction.to_f64(), [0.0, 0.0, -1.0]);
        let bottom_right = camera.primary_ray(camera.pixel(4, 4)).unwrap();
        assert_eq!(bottom_right.origin.to_f64(), [2.0, -1.0, 5.0]);
    }

    #[test]
    fn perspective_rays_start_at_the_eye() {
        let viewport = Viewport { x1: 0, x2: 2, y1: 0, y2: 2 };
        let window = Window { x1: -3.0, x2: 3.0, y1: -4.0, y2: 4.0 };
        let camera = Camera::<f64>::new(viewport, window, 0.0, Projection::Perspective { eye: [0.0, 0.0, 4.0] }).unwrap();
        let ray = camera.primary_ray(camera.pixel(2, 1)).unwrap();
        assert_eq!(ray.origin.to_f64(), [0.0, 0.0, 4.0]);
        let direction = ray.direction.to_f64();
        assert!(direction.iter().zip([0.6, 0.0, -0.8]).all(|(a, b)| (a - b).abs() < 1e-15), "{direction:?}");
    }

    #[test]
    fn zero_parallel_direction_is_rejected() {
        let viewport = Viewport { x1: 0, x2: 2, y1: 0, y2: 2 };
        let window = Window { x1: -3.0, x2: 3.0, y1: -4.0, y2: 4.0 };
        assert!(Camera::<f64>::new(viewport, window, 0.0, Projection::Parallel { direction: [0.0; 3] }).is_none());
    }
}
