//! An SSD0303 OLED controller (the EK-LM3S811's 96x16 OSRAM Pictiva, at I2C address 0x3D)
//! over the `embedded-hal` 1.0 [`I2c`] trait. One bit a dot, in pages of 8 rows (bit 0 the top
//! row of its page), the panel's 96 columns at the controller's columns 36 to 131. After the
//! address a control byte says what follows: 0x80 one command byte, 0x40 data bytes to the stop.
//!
//! The render's rows arrive as palette indices; each becomes dots by the core's error diffusion
//! (`ErrorDiffusion` over each entry's luma, `LutLuma`: the dots `microtrace render --display
//! ssd1306` and the Pico's SSD1306 show), one row of errors carried. Eight rows make a page,
//! kept here (96 bytes) and sent when its last row is done: the driver holds no more of the
//! picture than that.

use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Point, Size};
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::Pixel;
use embedded_hal::i2c::{I2c, Operation};
use microtrace::model::Palette;
use microtrace::pixel::{ColourMap, ErrorDiffusion, LutLuma};

use crate::display::RowDisplay;

pub const WIDTH: usize = 96;
pub const HEIGHT: usize = 16;
const ADDRESS: u8 = 0x3D;
/// The panel's first column in the controller's memory.
const FIRST_COLUMN: u8 = 36;
/// Control bytes: one command byte follows; data bytes follow.
const COMMAND: u8 = 0x80;
const DATA: u8 = 0x40;
const DISPLAY_ON: u8 = 0xAF;
const PAGE: u8 = 0xB0;
const COLUMN_LOW: u8 = 0x00;
const COLUMN_HIGH: u8 = 0x10;

/// The page being drawn: a byte a column, bit `y % 8` the row.
struct Page {
    bits: [u8; WIDTH],
}

impl OriginDimensions for Page {
    fn size(&self) -> Size {
        Size::new(WIDTH as u32, HEIGHT as u32)
    }
}

impl DrawTarget for Page {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(point, colour) in pixels {
            let (Ok(x), Ok(y)) = (usize::try_from(point.x), usize::try_from(point.y)) else { continue };
            let Some(column) = self.bits.get_mut(x) else { continue };
            let bit = 1u8 << (y % 8);
            if colour.is_on() {
                *column |= bit;
            } else {
                *column &= !bit;
            }
        }
        Ok(())
    }
}

pub struct Ssd0303<I2C> {
    i2c: I2C,
    dots: ErrorDiffusion<Page, WIDTH>,
    /// Pages that failed to send (a drawing error cannot be reported from inside the render).
    pub failed_pages: u16,
}

impl<I2C: I2c> Ssd0303<I2C> {
    /// Turns the display on and clears both pages.
    pub fn new(i2c: I2C) -> Result<Self, I2C::Error> {
        let mut display = Self { i2c, dots: ErrorDiffusion::new(Page { bits: [0; WIDTH] }), failed_pages: 0 };
        display.i2c.write(ADDRESS, &[COMMAND, DISPLAY_ON])?;
        for page in 0..(HEIGHT / 8) as u8 {
            display.send_page(page)?;
        }
        Ok(display)
    }

    /// Sends the page being drawn as page `page`: its address and first column, then its 96
    /// bytes.
    fn send_page(&mut self, page: u8) -> Result<(), I2C::Error> {
        self.i2c.write(ADDRESS, &[COMMAND, PAGE | page, COMMAND, COLUMN_LOW | (FIRST_COLUMN & 0x0F), COMMAND, COLUMN_HIGH | (FIRST_COLUMN >> 4)])?;
        self.i2c.transaction(ADDRESS, &mut [Operation::Write(&[DATA]), Operation::Write(&self.dots.target().bits)])
    }
}

impl<I2C: I2c> RowDisplay for Ssd0303<I2C> {
    /// The row's dots into the page; the page sent after its last row (the panel's first 96
    /// columns and 16 rows; the rest is not shown).
    fn show_row(&mut self, y: u16, indices: &[u8], palette: &Palette) {
        let row = usize::from(y);
        if row >= HEIGHT {
            return;
        }
        let luma = LutLuma::new(palette);
        let width = indices.len().min(WIDTH);
        let area = Rectangle::new(Point::new(0, i32::from(y)), Size::new(width as u32, 1));
        let Ok(()) = self.dots.fill_contiguous(&area, indices.iter().map(|index| luma.colour(*index)));
        if row % 8 == 7 || row + 1 == HEIGHT {
            if self.send_page((row / 8) as u8).is_err() {
                self.failed_pages = self.failed_pages.saturating_add(1);
            }
            self.dots.target_mut().bits = [0; WIDTH];
        }
    }
}
