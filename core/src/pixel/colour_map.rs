//! How a palette index becomes a display's colour: the one place each display path's mapping
//! is written, shared by the sinks, the firmware, the real-board examples and the tests.

use core::marker::PhantomData;

use embedded_graphics_core::pixelcolor::{PixelColor, Rgb888 as EgRgb888};

use crate::model::Palette;

/// A render's pixel (`P`: a palette index in PGA mode, the default; an
/// [`Rgb888`](crate::model::Rgb888) in RGB mode) -> a display colour.
pub trait ColourMap<P = u8> {
    /// The display's colour type.
    type Color: PixelColor;
    /// The colour `pixel` shows as.
    fn colour(&self, pixel: P) -> Self::Color;
}

/// The colour path: palette index -> look-up-table entry (4 bits a primary) -> 8 bits a
/// primary (level x 17) -> the display's colour type by embedded-graphics' own conversion
/// (`Rgb565::from(Rgb888)` rounds each primary to 5/6/5 bits).
#[derive(Debug)]
pub struct LutColour<'a, C> {
    pub palette: &'a Palette,
    colour: PhantomData<C>,
}

impl<'a, C> LutColour<'a, C> {
    pub const fn new(palette: &'a Palette) -> Self {
        Self { palette, colour: PhantomData }
    }
}

// Not derived: a derive would ask `C: Clone`.
impl<C> Clone for LutColour<'_, C> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<C> Copy for LutColour<'_, C> {}

/// The colour of a palette index on an RGB display of colour type `C`.
pub fn lut_colour<C: From<EgRgb888>>(palette: &Palette, index: u8) -> C {
    let [r, g, b] = palette.entry(index).to_rgb888();
    C::from(EgRgb888::new(r, g, b))
}

impl<C: PixelColor + From<EgRgb888>> ColourMap for LutColour<'_, C> {
    type Color = C;
    fn colour(&self, index: u8) -> C {
        lut_colour(self.palette, index)
    }
}

/// RGB mode's pixels on a colour display of colour type `C`: 8 bits a primary, by
/// embedded-graphics' own conversion (`Rgb565::from(Rgb888)` rounds each to 5/6/5 bits).
#[derive(Debug)]
pub struct RgbColour<C>(PhantomData<C>);

impl<C> RgbColour<C> {
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

impl<C> Default for RgbColour<C> {
    fn default() -> Self {
        Self::new()
    }
}

impl<C: PixelColor + From<EgRgb888>> ColourMap<crate::model::Rgb888> for RgbColour<C> {
    type Color = C;
    fn colour(&self, [r, g, b]: crate::model::Rgb888) -> C {
        C::from(EgRgb888::new(r, g, b))
    }
}
