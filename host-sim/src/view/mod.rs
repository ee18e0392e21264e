//! The simulator window of `microtrace view`: one concept per file.

pub mod colours;
pub mod depth_ranges;
pub mod enclosures;
pub mod fill;
pub mod keys;
pub mod preview;
pub mod rays;
pub mod overlay;
pub mod panel;
pub mod plan;
pub mod sink;
pub mod window;

#[cfg(test)]
mod test_scenes;
