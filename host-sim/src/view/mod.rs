//! The simulator window of `microtrace view`: one concept per file.

pub mod keys;
pub mod oled;
pub mod overlay;
pub mod panel;
pub mod sink;
pub mod window;
