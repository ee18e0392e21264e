//! The grey path: how a palette index shows on a 16-grey display (the lm3s6965evb's SSD0323
//! OLED, the simulator's OLED preview, and before the 1-bit dither the SSD1306).

use embedded_graphics_core::pixelcolor::{Gray4, Gray8};

use super::ColourMap;
use crate::model::Palette;

/// The grey level a palette index shows as on a 16-grey display: the look-up-table entry's
/// integer Rec. 601 luma, 0..=15 ([`crate::model::Rgb4::luminance`]).
pub fn grey_level(palette: &Palette, index: u8) -> Gray4 {
    Gray4::new(palette.entry(index).luminance())
}

/// [`grey_level`] as a [`ColourMap`].
#[derive(Clone, Copy, Debug)]
pub struct LutGrey<'a> {
    pub palette: &'a Palette,
}

impl<'a> LutGrey<'a> {
    pub const fn new(palette: &'a Palette) -> Self {
        Self { palette }
    }
}

impl ColourMap for LutGrey<'_> {
    type Color = Gray4;
    fn colour(&self, index: u8) -> Gray4 {
        grey_level(self.palette, index)
    }
}

/// How a palette index shows on an error-diffused 1-bit display before its tone curve: the
/// look-up-table entry's luma on an 8-bit scale ([`crate::model::Rgb4::luma8`]).
#[derive(Clone, Copy, Debug)]
pub struct LutLuma<'a> {
    pub palette: &'a Palette,
}

impl<'a> LutLuma<'a> {
    pub const fn new(palette: &'a Palette) -> Self {
        Self { palette }
    }
}

impl ColourMap for LutLuma<'_> {
    type Color = Gray8;
    fn colour(&self, index: u8) -> Gray8 {
        Gray8::new(self.palette.entry(index).luma8())
    }
}
