//! A display sink that sends each finished row at once: the render writes into a framebuffer
//! (which the Pixelbuffer optimization reads back), and `row_done` sends the finished row to
//! the `DrawTarget` as one `fill_contiguous` over the row's rectangle, through a
//! [`ColourMap`]. On an SPI panel driver (mipidsi's ST7789, ILI9341, ...) that is one address
//! window and one stream of pixels a row, where `draw_iter` with one pixel sets an address
//! window for every pixel. And the display never shows the Pixelbuffer's fill marks: only
//! finished rows reach it.

use embedded_graphics_core::prelude::{DrawTarget, Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use super::{ColourMap, FrameBuffer, PixelSink, PixelSource};

/// The render's sink for a display: a framebuffer of palette indices plus the display, sent a
/// finished row at a time. `offset` is where image pixel (0, 0) lands on the target.
#[derive(Debug)]
pub struct RowDisplaySink<'a, D, M> {
    pub frame: FrameBuffer<'a, u8>,
    pub target: D,
    pub map: M,
    pub offset: Point,
    /// Rows the target failed to take (a display error cannot be helped from inside the
    /// render; the render goes on and the caller can look here).
    pub failed_rows: u16,
}

impl<'a, D, M> RowDisplaySink<'a, D, M>
where
    D: DrawTarget,
    M: ColourMap<Color = D::Color>,
{
    pub fn new(frame: FrameBuffer<'a, u8>, target: D, map: M) -> Self {
        Self { frame, target, map, offset: Point::zero(), failed_rows: 0 }
    }

    /// Sends image row `y` (from the framebuffer) to the target as one contiguous fill.
    pub fn send_row(&mut self, y: u16) -> Result<(), D::Error> {
        let width = self.frame.width();
        if y >= self.frame.height() {
            return Ok(());
        }
        let start = usize::from(y) * usize::from(width);
        let Some(row) = self.frame.pixels().get(start..start + usize::from(width)) else { return Ok(()) };
        let area = Rectangle::new(self.offset + Point::new(0, i32::from(y)), Size::new(u32::from(width), 1));
        let map = &self.map;
        self.target.fill_contiguous(&area, row.iter().map(|index| map.colour(*index)))
    }
}

impl<D, M> PixelSink<u8> for RowDisplaySink<'_, D, M>
where
    D: DrawTarget,
    M: ColourMap<Color = D::Color>,
{
    fn set_pixel(&mut self, x: u16, y: u16, value: u8) {
        self.frame.set_pixel(x, y, value);
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        self.frame.write_row(x, y, values);
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: u8) {
        self.frame.fill_row(x, y, width, value);
    }

    fn row_done(&mut self, y: u16) {
        if self.send_row(y).is_err() {
            self.failed_rows = self.failed_rows.saturating_add(1);
        }
    }
}

impl<D, M> PixelSource<u8> for RowDisplaySink<'_, D, M> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<u8> {
        self.frame.get_pixel(x, y)
    }

    fn read_row(&self, x: u16, y: u16, values: &mut [u8]) {
        self.frame.read_row(x, y, values)
    }
}
