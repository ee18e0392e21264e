//! Scenes: the description a `.mts` file parses into ([`SceneDescription`](crate::model::SceneDescription), plain `f64`, no
//! number type yet) and the render-ready [`Scene`] prepared from it in a chosen number type.

mod prepared;
mod range;
mod warnings;

pub use prepared::*;
pub use warnings::SceneWarning;
