//! Where the render's palette indices go: a framebuffer in RAM (what the host receives, and
//! what the Pixelbuffer optimization reads back) and, on boards with one, the display, which is
//! flushed as each row finishes.

use core::convert::Infallible;

use embedded_graphics::pixelcolor::Gray4;
use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Size};
use embedded_graphics::Pixel;
use microtrace::pixel::{FrameBuffer, GreyDrawTargetSink, PixelSink, PixelSource};

/// A display that buffers drawing and sends it on `flush`.
pub trait FlushRows {
    fn flush(&mut self);
}

/// The display type of a board without one.
#[cfg_attr(feature = "lm3s6965evb", allow(dead_code))]
pub struct NoDisplay;

impl OriginDimensions for NoDisplay {
    fn size(&self) -> Size {
        Size::zero()
    }
}

impl DrawTarget for NoDisplay {
    type Color = Gray4;
    type Error = Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Gray4>>>(&mut self, _pixels: I) -> Result<(), Infallible> {
        Ok(())
    }
}

impl FlushRows for NoDisplay {
    fn flush(&mut self) {}
}

/// The render's sink: every pixel into the framebuffer, and into the display when there is one.
pub struct FramebufferAndDisplay<'a, D> {
    pub framebuffer: FrameBuffer<'a, u8>,
    pub display: Option<GreyDrawTargetSink<'a, D>>,
}

impl<D: DrawTarget<Color = Gray4> + FlushRows> PixelSink<u8> for FramebufferAndDisplay<'_, D> {
    fn set_pixel(&mut self, x: u16, y: u16, value: u8) {
        self.framebuffer.set_pixel(x, y, value);
        if let Some(display) = &mut self.display {
            display.set_pixel(x, y, value);
        }
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        self.framebuffer.write_row(x, y, values);
        if let Some(display) = &mut self.display {
            display.write_row(x, y, values);
        }
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: u8) {
        self.framebuffer.fill_row(x, y, width, value);
        if let Some(display) = &mut self.display {
            display.fill_row(x, y, width, value);
        }
    }

    /// Pixelbuffer's marks stay in the framebuffer: every one is overwritten before its row
    /// is done, so the display is sent only the picture.
    fn mark_row(&mut self, x: u16, y: u16, width: u16, value: u8) {
        self.framebuffer.fill_row(x, y, width, value);
    }

    fn row_done(&mut self, _y: u16) {
        if let Some(display) = &mut self.display {
            display.target.flush();
        }
    }
}

impl<D> PixelSource<u8> for FramebufferAndDisplay<'_, D> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<u8> {
        self.framebuffer.get_pixel(x, y)
    }

    fn read_row(&self, x: u16, y: u16, values: &mut [u8]) {
        self.framebuffer.read_row(x, y, values)
    }
}
