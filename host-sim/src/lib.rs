//! The desktop side of MicroTrace: the `microtrace` command's pieces, as a library so that the
//! integration tests can drive them.

pub mod allocation;
pub mod commands;
pub mod edges;
pub mod files;
pub mod heap;
pub mod image_difference;
pub mod number_type;
pub mod parallel;
pub mod progress;
pub mod rendering;
pub mod scene_file;
pub mod sphere_field;
pub mod window_binary;
