//! Shading (§4.2.4, §1.7.2; SHADE.C): the lighting terms, the PGA palette model, the RGB
//! model, the 4x4 dither and the roughness noise.

mod dither;
mod pga;
mod rgb;
mod roughness;

pub use dither::{dither_threshold, DITHER_4X4};
pub use pga::{pga_index, ShadingConstants};
pub use rgb::{rgb_intensity, rgb_pixel, rgb_quantized};
pub use roughness::roughness_sample;
