//! The two pixel modes (§4.2.4): PGA palette indices and 8-bit RGB, each a surface's own shade
//! and the ray tree's node colours.

use super::surface::NodeColours;
use crate::camera::PixelPosition;
use crate::model::{PreparedMaterial, Rgb888};
use crate::number::Number;
use crate::config::Config;
use crate::scene::Prepared;
use crate::light::Lighting;
use crate::shading::{dither_threshold, pga_index, rgb_intensity, rgb_pixel, rgb_quantized};

/// A mode's pixels: a surface's own (the thesis's shading) and the ray tree's node colours.
pub(crate) trait Mode<N>: NodeColours<N> {
    fn surface(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> Self::Pixel;
    /// The pixel of an antialiased mean (8-bit RGB) at screen (`screen_x`, `screen_y`).
    #[cfg(feature = "antialias")]
    fn averaged(&self, colour: [u8; 3], screen_x: u16, screen_y: u16) -> Self::Pixel;
}

/// PGA mode: a surface's palette index; a tree's node is its index's LUT colour, and a mixed
/// pixel the LUT entry nearest the mix moved by the pixel's ordered dither (scene format,
/// chapter 5; [`crate::model::Palette::dithered`]).
pub(crate) struct PgaNodes<'a, C: Config> {
    pub scene: &'a Prepared<C>,
}

impl<N: Number, C: Config<Number = N>> NodeColours<N> for PgaNodes<'_, C> {
    type Pixel = u8;
    fn finish(&self, colour: [N; 3], pixel: PixelPosition) -> u8 {
        let half = self.scene.constants.half;
        // Any value below zero clamps to 0 whether it was floored or truncated.
        let mixed = colour.map(|c| (c + half).to_i32_monotone().clamp(0, 255) as u8);
        self.scene.palette.dithered(mixed, dither_threshold(pixel.screen_x, pixel.screen_y))
    }
    fn local(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> [N; 3] {
        lut_colour(self.scene, self.surface(material, lighting, pixel))
    }
    fn background(&self) -> [N; 3] {
        lut_colour(self.scene, self.scene.background)
    }
}

#[cfg_attr(not(feature = "ray-tree"), allow(dead_code))]
fn lut_colour<N: Number, C: Config<Number = N>>(scene: &Prepared<C>, index: u8) -> [N; 3] {
    scene.palette.entry(index).to_rgb888().map(|c| N::from_i32(i32::from(c)))
}

impl<N: Number, C: Config<Number = N>> Mode<N> for PgaNodes<'_, C> {
    fn surface(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> u8 {
        pga_index(material, lighting, &self.scene.constants, self.scene.dither, pixel)
    }
    #[cfg(feature = "antialias")]
    fn averaged(&self, colour: [u8; 3], screen_x: u16, screen_y: u16) -> u8 {
        self.scene.palette.dithered(colour, dither_threshold(screen_x, screen_y))
    }
}

/// RGB mode: the channels' intensities, clamped and rounded (or dithered) once at the end.
pub(crate) struct RgbNodes<'a, C: Config> {
    pub scene: &'a Prepared<C>,
}

impl<N: Number, C: Config<Number = N>> NodeColours<N> for RgbNodes<'_, C> {
    type Pixel = Rgb888;
    fn finish(&self, colour: [N; 3], pixel: PixelPosition) -> Rgb888 {
        rgb_quantized(colour, &self.scene.constants, self.scene.dither, pixel)
    }
    fn local(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, _pixel: PixelPosition) -> [N; 3] {
        rgb_intensity(material, lighting, &self.scene.constants)
    }
    fn background(&self) -> [N; 3] {
        self.scene.background_rgb().map(|c| N::from_i32(i32::from(c)))
    }
}

impl<N: Number, C: Config<Number = N>> Mode<N> for RgbNodes<'_, C> {
    fn surface(&self, material: &PreparedMaterial<N>, lighting: Lighting<N>, pixel: PixelPosition) -> Rgb888 {
        rgb_pixel(material, lighting, &self.scene.constants, self.scene.dither, pixel)
    }
    #[cfg(feature = "antialias")]
    fn averaged(&self, colour: [u8; 3], _screen_x: u16, _screen_y: u16) -> Rgb888 {
        colour
    }
}

