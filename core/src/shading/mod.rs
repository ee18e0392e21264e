//! Shading (§4.2.4, SHADE.C): the PGA palette model and the RGB model, the look-up table, the
//! 4x4 dither and the roughness noise.

mod palette;

pub use palette::{Palette, Rgb4};
