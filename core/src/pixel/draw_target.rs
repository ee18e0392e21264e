//! Adapters from palette indices to any embedded-graphics `DrawTarget`, through the look-up
//! table, writing through to the target as the render goes (no framebuffer of their own): one
//! for colour displays, one for grey displays (the firmware's OLED). A run of pixels (`write_row`,
//! `fill_row`) goes to the target as one contiguous fill over the run's rectangle; a lone pixel
//! as one pixel. [`super::RowDisplaySink`] sends whole finished rows instead.

use embedded_graphics_core::pixelcolor::{Gray4, Rgb888 as EgRgb888};
use embedded_graphics_core::prelude::{DrawTarget, PixelColor, Point, Size};
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;

use super::{grey_level, lut_colour, PixelSink};
use crate::model::Palette;

/// Drives a colour `DrawTarget`: palette index -> LUT entry -> the target's colour.
#[derive(Debug)]
pub struct DrawTargetSink<'a, D> {
    pub target: D,
    pub palette: &'a Palette,
    /// Where image pixel (0, 0) lands on the target.
    pub offset: Point,
}

impl<D, C> PixelSink<u8> for DrawTargetSink<'_, D>
where
    D: DrawTarget<Color = C>,
    C: PixelColor + From<EgRgb888>,
{
    fn set_pixel(&mut self, x: u16, y: u16, index: u8) {
        let point = self.offset + Point::new(i32::from(x), i32::from(y));
        // A display that fails to draw one pixel cannot be helped from here; keep tracing.
        let _ = self.target.draw_iter(core::iter::once(Pixel(point, lut_colour::<C>(self.palette, index))));
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        let palette = self.palette;
        let area = row_rectangle(self.offset, x, y, values.len().min(usize::from(u16::MAX)) as u16);
        let _ = self.target.fill_contiguous(&area, values.iter().map(|index| lut_colour::<C>(palette, *index)));
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, index: u8) {
        let _ = self.target.fill_solid(&row_rectangle(self.offset, x, y, width), lut_colour::<C>(self.palette, index));
    }
}

/// The one-row rectangle of `width` pixels from image pixel (x, y), on the target.
fn row_rectangle(offset: Point, x: u16, y: u16, width: u16) -> Rectangle {
    Rectangle::new(offset + Point::new(i32::from(x), i32::from(y)), Size::new(u32::from(width), 1))
}

/// Drives a 16-grey `DrawTarget`: palette index -> LUT entry -> luminance 0..15 ([`grey_level`]).
#[derive(Debug)]
pub struct GreyDrawTargetSink<'a, D> {
    pub target: D,
    pub palette: &'a Palette,
    pub offset: Point,
}

impl<D> PixelSink<u8> for GreyDrawTargetSink<'_, D>
where
    D: DrawTarget<Color = Gray4>,
{
    fn set_pixel(&mut self, x: u16, y: u16, index: u8) {
        let point = self.offset + Point::new(i32::from(x), i32::from(y));
        let _ = self.target.draw_iter(core::iter::once(Pixel(point, grey_level(self.palette, index))));
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        let palette = self.palette;
        let area = row_rectangle(self.offset, x, y, values.len().min(usize::from(u16::MAX)) as u16);
        let _ = self.target.fill_contiguous(&area, values.iter().map(|index| grey_level(palette, *index)));
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, index: u8) {
        let _ = self.target.fill_solid(&row_rectangle(self.offset, x, y, width), grey_level(self.palette, index));
    }
}
