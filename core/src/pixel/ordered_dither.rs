//! The 1-bit path: 16 grey levels on a black-and-white display (an SSD1306) by 4x4 ordered
//! dither, with the core's one matrix, [`DITHER_4X4`] (RTRACE.C's `dither4`).
//!
//! In each aligned 4x4 block of the display, grey level `L` lights the `L` dots whose threshold
//! is below `L` (0 lights none, 1 one, ..., 14 fourteen), and full white (15) lights all 16: so
//! black is black and white is white, and each level but white lights one dot more than the
//! one below it (no level lights exactly 15 of 16; 16 levels cannot fill 17 dot counts).

use embedded_graphics_core::pixelcolor::{BinaryColor, Gray4, GrayColor};
use embedded_graphics_core::prelude::{Dimensions, DrawTarget, Point, PointsIter};
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;

use crate::shading::DITHER_4X4;

/// Whether the dot at display point `point` is lit for grey level `level` (0..=15).
pub fn dither_lights(level: u8, point: Point) -> bool {
    if level >= 15 {
        return true;
    }
    // rem_euclid: a point left of or above the display's origin keeps the pattern's phase.
    let column = point.x.rem_euclid(4) as usize;
    let row = point.y.rem_euclid(4) as usize;
    DITHER_4X4[column][row] < level
}

/// The 1-bit colour of grey `grey` at display point `point`.
pub fn dither_colour(grey: Gray4, point: Point) -> BinaryColor {
    if dither_lights(grey.luma(), point) {
        BinaryColor::On
    } else {
        BinaryColor::Off
    }
}

/// A 16-grey `DrawTarget` over a black-and-white one: every pixel dithered by its position on
/// the target. Contiguous fills stay contiguous fills on the target.
#[derive(Debug)]
pub struct OrderedDither<D>(pub D);

impl<D: Dimensions> Dimensions for OrderedDither<D> {
    fn bounding_box(&self) -> Rectangle {
        self.0.bounding_box()
    }
}

impl<D: DrawTarget<Color = BinaryColor>> DrawTarget for OrderedDither<D> {
    type Color = Gray4;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<Gray4>>>(&mut self, pixels: I) -> Result<(), D::Error> {
        self.0.draw_iter(pixels.into_iter().map(|Pixel(point, grey)| Pixel(point, dither_colour(grey, point))))
    }

    fn fill_contiguous<I: IntoIterator<Item = Gray4>>(&mut self, area: &Rectangle, colors: I) -> Result<(), D::Error> {
        self.0.fill_contiguous(area, area.points().zip(colors).map(|(point, grey)| dither_colour(grey, point)))
    }

    fn fill_solid(&mut self, area: &Rectangle, grey: Gray4) -> Result<(), D::Error> {
        match grey.luma() {
            0 => self.0.fill_solid(area, BinaryColor::Off),
            15 => self.0.fill_solid(area, BinaryColor::On),
            _ => self.0.fill_contiguous(area, area.points().map(|point| dither_colour(grey, point))),
        }
    }
}
