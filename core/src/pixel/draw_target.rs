//! Any embedded-graphics `DrawTarget` as a render's sink, through a [`ColourMap`]: written
//! through to the target as the render goes (no framebuffer of its own). A run of pixels
//! (`write_row`, `fill_row`) goes to the target as one contiguous fill over the run's
//! rectangle; a lone pixel as one pixel. [`super::RowDisplaySink`] sends whole finished rows
//! instead; [`Borrowed`] lends a display that outlives the render.

use embedded_graphics_core::prelude::{DrawTarget, Point, Size};
use embedded_graphics_core::geometry::Dimensions;
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;

use super::{ColourMap, LutGrey, PixelSink};

/// Drives a `DrawTarget` with a render's pixels (`P`) through `colours`: [`super::LutColour`]
/// for a colour display in PGA mode (palette index -> look-up-table entry -> the target's
/// colour), [`LutGrey`] for a 16-grey one, [`super::RgbColour`] for RGB mode.
#[derive(Debug)]
pub struct DrawTargetSink<D, M> {
    pub target: D,
    pub colours: M,
    /// Where image pixel (0, 0) lands on the target.
    pub offset: Point,
}

impl<P: Copy, D: DrawTarget, M: ColourMap<P, Color = D::Color>> PixelSink<P> for DrawTargetSink<D, M> {
    fn set_pixel(&mut self, x: u16, y: u16, pixel: P) {
        let point = self.offset + Point::new(i32::from(x), i32::from(y));
        // A display that fails to draw one pixel cannot be helped from here; keep tracing.
        let _ = self.target.draw_iter(core::iter::once(Pixel(point, self.colours.colour(pixel))));
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[P]) {
        let colours = &self.colours;
        let area = row_rectangle(self.offset, x, y, values.len().min(usize::from(u16::MAX)) as u16);
        let _ = self.target.fill_contiguous(&area, values.iter().map(|pixel| colours.colour(*pixel)));
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, pixel: P) {
        let _ = self.target.fill_solid(&row_rectangle(self.offset, x, y, width), self.colours.colour(pixel));
    }
}

/// A 16-grey display (the firmware's OLED): each palette index's look-up-table entry's
/// luminance 0..15 ([`super::grey_level`]).
pub type GreyDrawTargetSink<'a, D> = DrawTargetSink<D, LutGrey<'a>>;

/// The one-row rectangle of `width` pixels from image pixel (x, y), on the target.
fn row_rectangle(offset: Point, x: u16, y: u16, width: u16) -> Rectangle {
    Rectangle::new(offset + Point::new(i32::from(x), i32::from(y)), Size::new(u32::from(width), 1))
}

/// A borrowed draw target, so that a sink that owns its target can draw into a display that
/// outlives the render.
#[derive(Debug)]
pub struct Borrowed<'a, D>(pub &'a mut D);

impl<D: Dimensions> Dimensions for Borrowed<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.0.bounding_box()
    }
}

impl<D: DrawTarget> DrawTarget for Borrowed<'_, D> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<Self::Color>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        self.0.draw_iter(pixels)
    }

    fn fill_contiguous<I: IntoIterator<Item = Self::Color>>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error> {
        self.0.fill_contiguous(area, colors)
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), Self::Error> {
        self.0.fill_solid(area, color)
    }
}
