//! What the camera is made of, as written (§4.3): the viewport in pixels, the window on the
//! view plane, and the projection.

/// The screen rectangle in pixels, inclusive (`setviewport`). y grows upward, as on the PGA.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub x1: u16,
    pub x2: u16,
    pub y1: u16,
    pub y2: u16,
}

impl Viewport {
    /// Pixels across (1 for corners in the wrong order, which `Description::validate`
    /// refuses: never an overflow).
    pub const fn width(&self) -> u16 {
        self.x2.saturating_sub(self.x1).saturating_add(1)
    }
    /// Pixels down (as [`Viewport::width`]).
    pub const fn height(&self) -> u16 {
        self.y2.saturating_sub(self.y1).saturating_add(1)
    }
    pub const fn pixel_count(&self) -> u32 {
        self.width() as u32 * self.height() as u32
    }
}

/// The rectangle on the view plane that the viewport maps onto (`setwindow`); `x1 < x2`,
/// `y1 < y2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    pub x1: f64,
    pub x2: f64,
    pub y1: f64,
    pub y2: f64,
}

/// How rays leave the view plane (`perspective` / `parallel`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Rays start on the view plane and travel along `direction` (never zero).
    Parallel { direction: [f64; 3] },
    /// Rays start at `eye` and pass through the view plane.
    Perspective { eye: [f64; 3] },
}

