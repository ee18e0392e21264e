//! Adapters from palette indices to any embedded-graphics `DrawTarget`, through the look-up
//! table: one for colour displays, one for grey displays (the firmware's OLED).

use embedded_graphics_core::pixelcolor::{Gray4, Rgb888 as EgRgb888};
use embedded_graphics_core::prelude::{DrawTarget, PixelColor, Point, Size};
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;

use super::PixelSink;
use crate::shading::Palette;

/// Drives a colour `DrawTarget`: palette index -> LUT entry -> the target's colour.
#[derive(Debug)]
pub struct DrawTargetSink<'a, D> {
    pub target: D,
    pub palette: &'a Palette,
    /// Where image pixel (0, 0) lands on the target.
    pub offset: Point,
}

impl<'a, D, C> PixelSink<u8> for DrawTargetSink<'a, D>
where
    D: DrawTarget<Color = C>,
    C: PixelColor + From<EgRgb888>,
{
    fn set_pixel(&mut self, x: u16, y: u16, index: u8) {
        let [r, g, b] = self.palette.entry(index).to_rgb888();
        let point = self.offset + Point::new(x as i32, y as i32);
        // A display that fails to draw one pixel cannot be helped from here; keep tracing.
        let _ = self.target.draw_iter(core::iter::once(Pixel(point, C::from(EgRgb888::new(r, g, b)))));
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        let palette = self.palette;
        let origin = self.offset + Point::new(x as i32, y as i32);
        let pixels = values.iter().enumerate().map(|(offset, index)| {
            let [r, g, b] = palette.entry(*index).to_rgb888();
            Pixel(origin + Point::new(offset as i32, 0), C::from(EgRgb888::new(r, g, b)))
        });
        let _ = self.target.draw_iter(pixels);
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, index: u8) {
        let [r, g, b] = self.palette.entry(index).to_rgb888();
        let _ = self.target.fill_solid(&row_rectangle(self.offset, x, y, width), C::from(EgRgb888::new(r, g, b)));
    }
}

/// The one-row rectangle of `width` pixels from image pixel (x, y), on the target.
fn row_rectangle(offset: Point, x: u16, y: u16, width: u16) -> Rectangle {
    Rectangle::new(offset + Point::new(i32::from(x), i32::from(y)), Size::new(u32::from(width), 1))
}

/// Drives a 16-grey `DrawTarget`: palette index -> LUT entry -> luminance 0..15.
#[derive(Debug)]
pub struct GreyDrawTargetSink<'a, D> {
    pub target: D,
    pub palette: &'a Palette,
    pub offset: Point,
}

/// The grey level a palette index shows as on a 16-grey display.
pub(crate) fn grey_level(palette: &Palette, index: u8) -> Gray4 {
    Gray4::new(palette.entry(index).luminance())
}

impl<'a, D> PixelSink<u8> for GreyDrawTargetSink<'a, D>
where
    D: DrawTarget<Color = Gray4>,
{
    fn set_pixel(&mut self, x: u16, y: u16, index: u8) {
        let point = self.offset + Point::new(x as i32, y as i32);
        let _ = self.target.draw_iter(core::iter::once(Pixel(point, grey_level(self.palette, index))));
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        let palette = self.palette;
        let origin = self.offset + Point::new(x as i32, y as i32);
        let pixels = values
            .iter()
            .enumerate()
            .map(|(offset, index)| Pixel(origin + Point::new(offset as i32, 0), grey_level(palette, *index)));
        let _ = self.target.draw_iter(pixels);
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, index: u8) {
        let _ = self.target.fill_solid(&row_rectangle(self.offset, x, y, width), grey_level(self.palette, index));
    }
}

