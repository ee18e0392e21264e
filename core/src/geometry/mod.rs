//! Vectors, rays and affine transforms.

mod matrix;
mod ray;
pub mod reflection;
mod transform;
mod vector;

pub use matrix::Matrix4;
pub use ray::Ray;
pub use transform::AffineTransform;
pub use vector::Vector3;
