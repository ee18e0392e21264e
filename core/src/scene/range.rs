//! Range checks at scene preparation: a scene whose values do not fit the number type is
//! rejected with an error that names the object's line, instead of rendering with saturated
//! (silently wrong) arithmetic. Everything is checked in `f64` against
//! [`Number::can_represent`]:
//! - the camera (the eye, or the window's corners on the view plane) and a point light;
//! - per object: its transformed bounding volume, the entries of its transform and of the
//!   inverse the tracer holds in the number type, and every point a ray can start from, taken
//!   into the object's own space. There the tracer squares coordinates, and a small or thin
//!   object far from the eye has large ones (distance over its smallest scale).
//!
//! The limits and what they mean per number type are in docs/hard-cases.md.

use crate::geometry::Matrix4;
use crate::number::Number;
use crate::optimize::bounding_volume::unit_volume;
use crate::model::{SceneError, SceneErrorKind};
use crate::model::{Description, Light, ObjectDescription, Projection};

/// The axis-aligned box of every point a ray can start from: the eye or the window on the view
/// plane for primary rays and, with shadows on, every object's bounding volume for shadow rays.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayOrigins {
    low: [f64; 3],
    high: [f64; 3],
}

impl RayOrigins {
    pub fn of<L>(description: &Description<L>, objects: &[ObjectDescription]) -> Self {
        let mut origins = match description.projection {
            Projection::Perspective { eye } => Self { low: eye, high: eye },
            Projection::Parallel { .. } => {
                let window = description.window;
                Self {
                    low: [window.x1, window.y1, description.view_plane],
                    high: [window.x2, window.y2, description.view_plane],
                }
            }
        };
        if description.shadows {
            for object in objects {
                for vertex in world_volume(object) {
                    origins.include(vertex);
                }
            }
        }
        origins
    }

    fn include(&mut self, point: [f64; 3]) {
        for ((low, high), coordinate) in self.low.iter_mut().zip(&mut self.high).zip(point) {
            *low = low.min(coordinate);
            *high = high.max(coordinate);
        }
    }

    /// The box's eight corners: an affine map's extremes over the box are at its corners.
    fn corners(&self) -> [[f64; 3]; 8] {
        core::array::from_fn(|i| {
            core::array::from_fn(|axis| if i >> axis & 1 == 0 { self.low[axis] } else { self.high[axis] })
        })
    }
}

fn world_volume(object: &ObjectDescription) -> [[f64; 3]; 8] {
    unit_volume(object.primitive).map(|vertex| object.world_from_object.transform_point(vertex))
}

/// The largest magnitude among `values`; NaN if any is NaN (so that it fails the check).
fn largest(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().fold(0.0, |largest: f64, value| if value.is_nan() || largest.is_nan() { f64::NAN } else { largest.max(value.abs()) })
}

fn matrix_entries(matrix: &Matrix4) -> impl Iterator<Item = f64> + '_ {
    matrix.rows.iter().flat_map(|row| row[..3].iter().copied())
}

fn check<N: Number>(line: u32, what: &'static str, value: f64) -> Result<(), SceneError> {
    if N::can_represent(value) {
        Ok(())
    } else {
        Err(SceneError::new(line, SceneErrorKind::OutOfRangeForNumberType { what, number: N::NAME, value, limit: N::SCENE_LIMIT }))
    }
}

/// Checks one object, given its inverse transform and the scene's ray origins.
pub fn check_object<N: Number>(object: &ObjectDescription, inverse: &Matrix4, origins: &RayOrigins) -> Result<(), SceneError> {
    let line = object.line;
    check::<N>(line, "the object's bounding volume", largest(world_volume(object).into_iter().flatten()))?;
    check::<N>(line, "the object's transform", largest(matrix_entries(&object.world_from_object)))?;
    check::<N>(line, "the object's inverse transform (one over its smallest scale)", largest(matrix_entries(inverse)))?;
    let local = origins.corners().map(|corner| inverse.transform_point(corner));
    check::<N>(
        line,
        "the distance from the eye, the window or (with shadows) another object, in units of the object's smallest scale,",
        largest(local.into_iter().flatten()),
    )
}

/// Checks the camera and a point light (a directional light is a unit vector). Each error names
/// the line of the statement that set the value (`description.lines`; 0 for a default).
pub fn check_camera_and_light<N: Number, L>(description: &Description<L>) -> Result<(), SceneError> {
    let (window, lines) = (description.window, description.lines);
    check::<N>(lines.window, "the window", largest([window.x1, window.x2, window.y1, window.y2]))?;
    check::<N>(lines.view_plane, "the view plane distance", description.view_plane.abs())?;
    if let Projection::Perspective { eye } = description.projection {
        check::<N>(lines.projection, "the eye", largest(eye))?;
    }
    if let Light::Point(position) = description.light {
        check::<N>(lines.light, "the light", largest(position))?;
    }
    Ok(())
}

#[cfg(all(test, feature = "fixed-point"))]
mod tests;
