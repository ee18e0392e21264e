//! The four screen-space optimizations for primary rays (§4.7): Pixelbuffer, Extents, Grid and
//! Sortlist, plus shadow-ray culling. Each only skips work whose result is known, so every
//! combination renders the same image as none (see docs/optimizations.md).
//!
//! One file per concept: [`bounding_volume`] (the four stored unit volumes, transformed on
//! demand), [`projection`] (`projectvolume`), [`extents`], [`grid`], [`sortlist`],
//! [`pixelbuffer`] (the fill) and [`shadow_culling`].

mod acceleration;
mod build_options;

pub mod bounding_sphere;
pub mod bounding_volume;
pub mod bvh;
#[cfg(feature = "acceleration-tables")]
pub mod early_split;
pub mod capsule;
pub mod extents;
pub mod grid;
pub mod pixelbuffer;
pub mod projection;
pub mod shadow_culling;
#[cfg(feature = "csg")]
pub mod solid_extents;
pub mod space_grid;
pub mod sortlist;

pub use acceleration::{window_corners, Acceleration, AccelerationParts, ObjectBounds, Tuning};
#[cfg(feature = "acceleration-tables")]
pub use acceleration::{baked_hierarchy, hierarchy_references, HierarchyScratch, BAKED_HIERARCHY_ABOVE};
pub use acceleration::HIERARCHY_ABOVE;
pub use build_options::{SILHOUETTES, TABLES};
