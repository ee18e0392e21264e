//! RGB mode. The thesis's `rgbshade` subtracted the light from white, so more light gave a
//! darker pixel, added the ambient term twice and added `16·clr` to every byte (digest §6.6,
//! §11 B6). Ours is additive and physically sensible: the surface reflects `1 − cmy` of each
//! primary (cyan ink absorbs red, and so on), the light is white, the highlight is white.
//!
//! `channel = 255·(ka·Ia·ρ + kd·diff·ρ + ks·spec)`, clamped to [0, 254.9], rounded or dithered
//! like the PGA shade.

use super::ShadingConstants;
use crate::light::Lighting;
use crate::camera::PixelPosition;
use crate::number::Number;
use crate::model::Rgb888;
use crate::model::PreparedMaterial;

pub fn rgb_pixel<N: Number>(
    material: &PreparedMaterial<N>,
    light: Lighting<N>,
    constants: &ShadingConstants<N>,
    dither: bool,
    pixel: PixelPosition,
) -> Rgb888 {
    rgb_quantized(rgb_intensity(material, light, constants), constants, dither, pixel)
}

/// The three channels' intensities on a 0..255 scale, before clamping and rounding.
pub fn rgb_intensity<N: Number>(material: &PreparedMaterial<N>, light: Lighting<N>, constants: &ShadingConstants<N>) -> [N; 3] {
    let specular = material.ks * light.specular;
    let diffuse = material.kd * light.diffuse + material.ka * constants.ambient;
    core::array::from_fn(|channel| constants.full_rgb * (diffuse * material.reflectance[channel] + specular))
}

/// Intensities clamped to [0, 254.9] and rounded or dithered to bytes.
pub fn rgb_quantized<N: Number>(intensity: [N; 3], constants: &ShadingConstants<N>, dither: bool, pixel: PixelPosition) -> Rgb888 {
    intensity.map(|channel| constants.quantize(channel, constants.brightest_rgb, dither, pixel).clamp(0, 255) as u8)
}
