//! MicroTrace: a `no_std` re-creation of the ray tracer of Eugene Curran's 1989 MSc thesis
//! *Ray Tracing Under The Microcomputer* (Dublin City University).
//!
//! Module map (thesis sections in brackets):
//! - [`number`]: the number trait the whole tracer is generic over (f64, f32, fixed point).
//! - [`geometry`]: vectors, rays and the row-vector affine transforms of §1.5.1.
//! - [`model`]: what a scene is made of: primitives, view, materials, lights, colours, the
//!   scene as written, and the error type. Imports nothing above `geometry`.
//! - [`light`]: the lights in the number type and their shading terms (§4.2.4, digest §6.2).
//! - [`shapes`]: the four unit primitives of §4.2.5 with `intersect` and `occluded` (§4.5–4.6).
//! - [`camera`]: window/viewport mapping and primary rays (§4.3).
//! - [`shading`]: the PGA and RGB shading models, look-up table, dither, roughness (§4.2.4).
//! - [`scene`]: the parsed scene description and the prepared, render-ready scene.
//! - [`parser`]: the `.mts` scene format.
//! - [`render`]: the per-pixel driver and the statistics of Table 4.2.
//! - [`optimize`]: the four screen-space optimizations of §4.7.
//! - [`formats`]: the thesis's image and look-up-table file formats (§4.2.2–4.2.3).
//! - [`pixel`]: the `PixelSink` / `PixelSource` traits and their implementations.
#![no_std]
#![forbid(unsafe_code)]
// Cargo.toml denies unwrap/expect/panic in the core; its unit tests may use them.
#![cfg_attr(test, allow(clippy::unwrap_used, clippy::expect_used, clippy::panic))]
#![warn(missing_debug_implementations)]

#[cfg(feature = "alloc")]
extern crate alloc;

pub mod bake;
pub mod camera;
pub mod config;
pub mod csg;
pub mod formats;
pub mod geometry;
pub mod light;
pub mod model;
pub mod number;
pub mod optimize;
pub mod parser;
pub mod pixel;
pub mod render;
pub mod scene;
pub mod shading;
pub mod shapes;
pub mod storage;
