//! The lights in the render's number type: the thesis's one light (§4.2.4) and chapter 5's
//! further lights with their intensities.

use crate::geometry::Vector3;
use crate::model::{Light, SceneError, SceneErrorKind};
use crate::number::Number;

/// A light as the render needs it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PreparedLight<N> {
    Point(Vector3<N>),
    /// Unit vector toward the light.
    Direction(Vector3<N>),
}

/// A light beyond the first, with its intensity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedLightSource<N> {
    pub light: PreparedLight<N>,
    pub intensity: N,
}

impl<N: Number> PreparedLight<N> {
    /// A light in the number type; a direction is normalised (`line`: where it was written).
    pub fn new(light: Light, line: u32) -> Result<Self, SceneError> {
        Ok(match light {
            Light::Point(position) => PreparedLight::Point(Vector3::from_f64(position)),
            Light::Direction(direction) => {
                let length = libm::sqrt(direction.iter().map(|c| c * c).sum::<f64>());
                if length == 0.0 || !length.is_finite() {
                    return Err(SceneError { line, kind: SceneErrorKind::ZeroDirection });
                }
                PreparedLight::Direction(Vector3::from_f64(direction.map(|c| c / length)))
            }
        })
    }
}
