//! Lights: their data in the render's number type ([`PreparedLight`], prepared from the
//! model's [`Light`](crate::model::Light)) and the shading terms they give at a surface
//! ([`lighting`]: diffuse and Blinn's specular, digest §6.2). The render sums them over the
//! lights with a shadow ray each (`render/direct_lighting.rs`).

mod source;
mod terms;

pub use source::{PreparedLight, PreparedLightSource};
pub use terms::{lighting, Lighting};
