//! Where the render's palette indices go: row by row to the host (`framebuffer.bin`) and, on
//! boards with one, to the display, each row as soon as it is finished. No framebuffer: the
//! streamed render (`microtrace::render::render` in the order `Streamed`) writes each row once and
//! never reads it back, so one row of palette indices is all the firmware keeps (on the stack,
//! `StreamedRows`). With the `framebuffer` feature (the framebuffer render, which Pixelbuffer
//! reads back) or `progressive` (whose passes write each row four times), the picture is kept in
//! a RAM framebuffer instead (`FramebufferAndDisplay`) and written to the host after the render.

use embedded_graphics::pixelcolor::GrayColor;
use microtrace::pixel::{grey_level, PixelSink};
#[cfg(any(feature = "framebuffer", feature = "progressive"))]
use microtrace::pixel::{FrameBuffer, PixelSource};
use microtrace::model::Palette;

#[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
use crate::semihosting::HostFile;

/// A display that shows whole rows: the row's palette indices, left to right, which it maps
/// through the scene's look-up table to what it can show (16 greys, or dots).
pub trait RowDisplay {
    fn show_row(&mut self, y: u16, indices: &[u8], palette: &Palette);
}

/// The display type of a board without one.
#[cfg_attr(feature = "lm3s6965evb", allow(dead_code))]
pub struct NoDisplay;

impl RowDisplay for NoDisplay {
    fn show_row(&mut self, _y: u16, _indices: &[u8], _palette: &Palette) {}
}

/// The grey levels (0..15) of a row of palette indices (the core's `grey_level`, the LUT
/// entry's luminance), worked out once for each run of equal indices.
#[cfg_attr(not(feature = "lm3s6965evb"), allow(dead_code))]
pub fn levels<'a>(palette: &'a Palette, indices: &'a [u8]) -> impl Iterator<Item = u8> + 'a {
    let mut last: Option<(u8, u8)> = None;
    indices.iter().map(move |&index| match last {
        Some((seen, level)) if seen == index => level,
        _ => {
            let level = grey_level(palette, index).luma();
            last = Some((index, level));
            level
        }
    })
}

/// The streamed render's sink: the row being traced, sent to the host and the display when it
/// is done. Every pixel of a row is written before its `row_done` (the streamed render's
/// promise), so nothing of an earlier row is needed.
#[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
pub struct StreamedRows<'a, D, const WIDTH: usize> {
    row: [u8; WIDTH],
    host: HostFile,
    pub display: Option<D>,
    palette: &'a Palette,
    /// Rows the host did not take whole (reported after the render: the render cannot stop).
    pub failed_writes: u16,
    /// The bytes sent to the host: the whole picture's once the render is done.
    pub sent_bytes: usize,
}

#[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
impl<'a, D: RowDisplay, const WIDTH: usize> StreamedRows<'a, D, WIDTH> {
    pub fn new(host: HostFile, display: Option<D>, palette: &'a Palette) -> Self {
        Self { row: [0; WIDTH], host, display, palette, failed_writes: 0, sent_bytes: 0 }
    }
}

#[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
impl<D: RowDisplay, const WIDTH: usize> PixelSink<u8> for StreamedRows<'_, D, WIDTH> {
    fn set_pixel(&mut self, x: u16, _y: u16, value: u8) {
        if let Some(pixel) = self.row.get_mut(usize::from(x)) {
            *pixel = value;
        }
    }

    fn write_row(&mut self, x: u16, _y: u16, values: &[u8]) {
        for (pixel, value) in self.row.iter_mut().skip(usize::from(x)).zip(values) {
            *pixel = *value;
        }
    }

    fn fill_row(&mut self, x: u16, _y: u16, width: u16, value: u8) {
        // A slice's fill (word stores), not a byte at a time through an iterator.
        let (start, end) = (usize::from(x).min(WIDTH), (usize::from(x) + usize::from(width)).min(WIDTH));
        if let Some(run) = self.row.get_mut(start..end) {
            run.fill(value);
        }
    }

    fn row_done(&mut self, y: u16) {
        if self.host.write_all(&self.row) {
            self.sent_bytes += WIDTH;
        } else {
            self.failed_writes = self.failed_writes.saturating_add(1);
        }
        if let Some(display) = &mut self.display {
            display.show_row(y, &self.row, self.palette);
        }
    }
}

/// The framebuffer render's and the progressive render's sink: every pixel into the
/// framebuffer; each finished row sent from it to the display, when there is one.
#[cfg(any(feature = "framebuffer", feature = "progressive"))]
pub struct FramebufferAndDisplay<'a, D> {
    pub framebuffer: FrameBuffer<'a, u8>,
    pub display: Option<D>,
    pub palette: &'a Palette,
}

#[cfg(any(feature = "framebuffer", feature = "progressive"))]
impl<D: RowDisplay> PixelSink<u8> for FramebufferAndDisplay<'_, D> {
    fn set_pixel(&mut self, x: u16, y: u16, value: u8) {
        self.framebuffer.set_pixel(x, y, value);
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        self.framebuffer.write_row(x, y, values);
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: u8) {
        self.framebuffer.fill_row(x, y, width, value);
    }

    /// Pixelbuffer's marks are overwritten before their row is done: the display is sent only
    /// finished rows, so it never shows them.
    fn mark_row(&mut self, x: u16, y: u16, width: u16, value: u8) {
        self.framebuffer.fill_row(x, y, width, value);
    }

    fn row_done(&mut self, y: u16) {
        let Some(display) = &mut self.display else { return };
        let width = usize::from(self.framebuffer.width());
        let start = usize::from(y) * width;
        if let Some(row) = self.framebuffer.pixels().get(start..start + width) {
            display.show_row(y, row, self.palette);
        }
    }
}

#[cfg(any(feature = "framebuffer", feature = "progressive"))]
impl<D> PixelSource<u8> for FramebufferAndDisplay<'_, D> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<u8> {
        self.framebuffer.get_pixel(x, y)
    }

    fn read_row(&self, x: u16, y: u16, values: &mut [u8]) {
        self.framebuffer.read_row(x, y, values)
    }
}
