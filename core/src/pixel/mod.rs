//! Where the renderer's pixels go, and where the Pixelbuffer optimization reads them back.
//!
//! Coordinates here are *image* coordinates: `x` from the left, `y` = row from the **top**
//! (row 0 is the viewport's top row, screen y = vy2). The renderer produces rows top first, as
//! the thesis's `pgatrace` did (§3.4 of the digest).
//!
//! In the style of embedded-graphics: one required method per trait, and defaulted row
//! methods that an implementation can replace with a faster path.

mod frame_buffer;
mod mock;
#[cfg(feature = "embedded-graphics")]
mod colour_map;
#[cfg(feature = "embedded-graphics")]
mod draw_target;
#[cfg(feature = "embedded-graphics")]
mod error_diffusion;
#[cfg(feature = "embedded-graphics")]
mod grey;
#[cfg(feature = "embedded-graphics")]
mod ordered_dither;
#[cfg(feature = "embedded-graphics")]
mod row_display;

pub use frame_buffer::FrameBuffer;
pub use mock::MockSink;
#[cfg(feature = "embedded-graphics")]
pub use colour_map::{lut_colour, ColourMap, LutColour, RgbColour};
#[cfg(feature = "embedded-graphics")]
pub use draw_target::{Borrowed, DrawTargetSink, GreyDrawTargetSink};
#[cfg(feature = "embedded-graphics")]
pub use error_diffusion::{tone, ErrorDiffusion};
#[cfg(feature = "embedded-graphics")]
pub use grey::{grey_level, LutGrey, LutLuma};
#[cfg(feature = "embedded-graphics")]
pub use ordered_dither::{dither_colour, dither_lights, OrderedDither};
#[cfg(feature = "embedded-graphics")]
pub use row_display::RowDisplaySink;

/// Something that accepts pixels of type `P`: palette indices (`u8`) in PGA mode, [`Rgb888`](crate::model::Rgb888)
/// in RGB mode.
pub trait PixelSink<P: Copy> {
    /// Stores one pixel. Coordinates outside the sink are ignored.
    fn set_pixel(&mut self, x: u16, y: u16, value: P);

    /// Stores a run of pixels of row `y` starting at column `x`.
    fn write_row(&mut self, x: u16, y: u16, values: &[P]) {
        for (offset, value) in values.iter().enumerate() {
            self.set_pixel(x.saturating_add(offset as u16), y, *value);
        }
    }

    /// Fills `width` pixels of row `y` from column `x` with one value.
    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        for offset in 0..width {
            self.set_pixel(x.saturating_add(offset), y, value);
        }
    }

    /// Pixelbuffer's marks (§4.7.2): `width` pixels of row `y` from column `x` set to `value`
    /// before the render, read back by it (through [`PixelSource`]) and overwritten before the
    /// row is done. A sink that also shows its pixels (a display) need not show these; by
    /// default they are stored as [`PixelSink::fill_row`] stores them.
    fn mark_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        self.fill_row(x, y, width, value);
    }

    /// Called after each finished row; a display can flush here, a host can report progress.
    fn row_done(&mut self, _y: u16) {}
}

/// Something the renderer can read pixels back from (the Pixelbuffer's `rline`, §4.7.2).
pub trait PixelSource<P: Copy> {
    /// The pixel at (x, y), or `None` outside the source.
    fn get_pixel(&self, x: u16, y: u16) -> Option<P>;

    /// Reads row `y` from column `x` into `values`; pixels outside the source are left alone.
    fn read_row(&self, x: u16, y: u16, values: &mut [P]) {
        for (offset, value) in values.iter_mut().enumerate() {
            if let Some(pixel) = self.get_pixel(x.saturating_add(offset as u16), y) {
                *value = pixel;
            }
        }
    }
}

impl<P: Copy, S: PixelSink<P> + ?Sized> PixelSink<P> for &mut S {
    fn set_pixel(&mut self, x: u16, y: u16, value: P) {
        (**self).set_pixel(x, y, value)
    }
    fn write_row(&mut self, x: u16, y: u16, values: &[P]) {
        (**self).write_row(x, y, values)
    }
    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        (**self).fill_row(x, y, width, value)
    }
    fn mark_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        (**self).mark_row(x, y, width, value)
    }
    fn row_done(&mut self, y: u16) {
        (**self).row_done(y)
    }
}

impl<P: Copy, S: PixelSource<P> + ?Sized> PixelSource<P> for &mut S {
    fn get_pixel(&self, x: u16, y: u16) -> Option<P> {
        (**self).get_pixel(x, y)
    }
    fn read_row(&self, x: u16, y: u16, values: &mut [P]) {
        (**self).read_row(x, y, values)
    }
}

#[cfg(test)]
mod tests;
