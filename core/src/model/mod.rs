//! The model: what a scene is made of, before any number type does work on it. The bottom
//! layer of the crate above `number` and `geometry`: every other module may import it, and it
//! imports none of them (docs/architecture.md; `tests/layers.rs` checks).
//!
//! - [`Primitive`]: the closed set of primitives (§4.2.5);
//! - [`SolidNode`], [`Operation`]: solids of constructive solid geometry as written (§3.2);
//! - [`Viewport`], [`Window`], [`Projection`]: the camera as written (§4.3);
//! - [`Material`] and [`PreparedMaterial`]: surface constants (table 4.1);
//! - [`Light`], [`LightSource`]: the lights as written;
//! - [`Rgb4`], [`Palette`], [`Rgb888`]: the PGA's look-up table and the RGB pixel;
//! - [`Optimizations`]: which of §4.7's optimizations are on;
//! - [`SceneDescription`]: a whole scene as written, which the parser produces;
//! - [`SceneError`]: what is wrong with a scene, from the parser or from preparation.

mod colour;
mod description;
mod error;
mod extent;
mod light;
mod material;
mod object;
mod object_description;
mod optimizations;
mod primitive;
mod solid;
pub(crate) mod validate;
mod view;

pub use colour::{Palette, Rgb4, Rgb888};
pub use description::{Antialias, Description, SceneDescription, SettingLines, DEFAULT_DEPTH, MAX_DEPTH};
pub use object_description::ObjectDescription;
pub use extent::Extent;
pub use error::{SceneError, SceneErrorKind, Token, TOKEN_EXCERPT_BYTES};
pub use light::{Light, LightSource, MAX_LIGHTS};
pub use material::{Material, PreparedMaterial};
pub use object::{Object, Objects};
pub use optimizations::Optimizations;
pub use primitive::{Primitive, SolidRange, Taper, Tube, VertexNormals};
pub use solid::{enclosing_transform, for_each_node_box, solid_needs_and_box, Operation, PreparedSolidNode, SolidNeeds, SolidNode, MAX_HELD_SPANS, MAX_SOLID_NODES, NO_SKIP, MAX_SOLID_STACK, MAX_SPANS};
pub use view::{Projection, Viewport, Window};
pub(crate) use validate::{IntegerRange, RealRange};
pub(crate) use validate as ranges;
