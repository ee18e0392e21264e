//! Viewing (§4.3, RTRACE.C:generateray): the window/viewport mapping, parallel and perspective
//! primary rays, and fitting a scene to another screen size.

mod fit;
mod view;

pub use view::{Camera, PixelPosition};
