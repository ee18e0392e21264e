//! An SSD0323 OLED controller as an embedded-graphics `DrawTarget<Color = Gray4>`, over the
//! `embedded-hal` 1.0 traits: any [`SpiDevice`] for the bytes and any [`OutputPin`] for the
//! data/command line (this board's SSI0 and PC7 are in `spi.rs`; another board's HAL types fit
//! as they are). Drawing changes a 4-bit copy of the screen in RAM (4 KB) and marks rows dirty;
//! `flush` sends the dirty rows. Pixel layout (qemu.md): two pixels per byte, high nibble =
//! left pixel, 64 bytes per row; 128x64 shown.

use core::convert::Infallible;

use embedded_graphics::pixelcolor::{Gray4, GrayColor};
use embedded_graphics::prelude::{Dimensions, DrawTarget, OriginDimensions, Size};
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::Pixel;
use embedded_hal::digital::OutputPin;
use embedded_hal::spi::SpiDevice;

use crate::display::FlushRows;

pub const WIDTH: usize = 128;
pub const HEIGHT: usize = 64;
const BYTES_PER_ROW: usize = WIDTH / 2;

/// The screen's contents, one nibble per pixel.
pub type ScreenCopy = [[u8; BYTES_PER_ROW]; HEIGHT];

/// Commands: set the column window (byte units) and the row window; data then auto-increments
/// inside the window.
const SET_COLUMN_WINDOW: u8 = 0x15;
const SET_ROW_WINDOW: u8 = 0x75;

/// A power-on set-up for the board's RIT P14201 panel in the manner of TI's rit128x96x4 driver:
/// display off, segment remap, start line, offset, normal display, multiplex 64 rows, phase
/// length, row period, clock, pre-charge, VCOMH, display on. QEMU accepts all of these and
/// ignores the set-up ones (shared/research/qemu.md), so their values are untested on real hardware; in
/// particular the remap byte decides the nibble order this driver assumes (high = left).
const INITIALISATION: [u8; 21] = [
    0xAE, // display off
    0xA0, 0x52, // remap: column address and nibble order as the panel is wired
    0xA1, 0x00, // start line 0
    0xA2, 0x4C, // display offset
    0xA4, // normal display
    0xA8, 0x3F, // multiplex ratio: 64 rows
    0xB1, 0x22, // phase length
    0xB2, 0x46, // row period
    0xB3, 0x91, // display clock
    0xBC, 0x10, // pre-charge voltage
    0xBE, 0x1C, // VCOMH
    0xAF, // display on
];

/// A failure to talk to the controller: the SPI device's or the data/command line's.
#[derive(Debug)]
pub enum Error<S, P> {
    Spi(S),
    DataCommand(P),
}

pub struct Ssd0323<SPI, DC> {
    spi: SPI,
    data_command: DC,
    /// The level the data/command line was last set to (`None`: not yet set).
    sending_data: Option<bool>,
    screen: &'static mut ScreenCopy,
    /// Bit y set: row y differs from the controller's RAM.
    dirty_rows: u64,
    /// Flushes that failed (a drawing error cannot be reported from inside the render).
    pub failed_flushes: u16,
}

impl<SPI: SpiDevice<u8>, DC: OutputPin> Ssd0323<SPI, DC> {
    /// Initialises the controller and clears the screen.
    pub fn new(spi: SPI, data_command: DC, screen: &'static mut ScreenCopy) -> Result<Self, Error<SPI::Error, DC::Error>> {
        for row in screen.iter_mut() {
            row.fill(0);
        }
        let mut display = Self { spi, data_command, sending_data: None, screen, dirty_rows: u64::MAX, failed_flushes: 0 };
        display.send(false, &INITIALISATION)?;
        display.flush()?;
        Ok(display)
    }

    /// Sends the dirty rows, each as one command transaction (its window) and one data
    /// transaction (its 64 bytes).
    pub fn flush(&mut self) -> Result<(), Error<SPI::Error, DC::Error>> {
        while self.dirty_rows != 0 {
            let y = self.dirty_rows.trailing_zeros() as usize;
            self.dirty_rows &= !(1u64 << y);
            self.send(false, &[SET_COLUMN_WINDOW, 0, (BYTES_PER_ROW - 1) as u8, SET_ROW_WINDOW, y as u8, y as u8])?;
            let Some(row) = self.screen.get(y) else { continue };
            set_level(&mut self.data_command, &mut self.sending_data, true)?;
            self.spi.write(row).map_err(Error::Spi)?;
        }
        Ok(())
    }

    /// Sends command (`data` false) or data bytes.
    fn send(&mut self, data: bool, bytes: &[u8]) -> Result<(), Error<SPI::Error, DC::Error>> {
        set_level(&mut self.data_command, &mut self.sending_data, data)?;
        self.spi.write(bytes).map_err(Error::Spi)
    }
}

/// Sets the data/command line, when it is not at that level already. The SPI device's
/// transactions end with the bus flushed, so no byte is still leaving when it changes.
fn set_level<DC: OutputPin, S>(line: &mut DC, level: &mut Option<bool>, data: bool) -> Result<(), Error<S, DC::Error>> {
    if *level != Some(data) {
        if data { line.set_high() } else { line.set_low() }.map_err(Error::DataCommand)?;
        *level = Some(data);
    }
    Ok(())
}

impl<SPI: SpiDevice<u8>, DC: OutputPin> FlushRows for Ssd0323<SPI, DC> {
    fn flush(&mut self) {
        if Ssd0323::flush(self).is_err() {
            self.failed_flushes = self.failed_flushes.saturating_add(1);
        }
    }
}

impl<SPI, DC> OriginDimensions for Ssd0323<SPI, DC> {
    fn size(&self) -> Size {
        Size::new(WIDTH as u32, HEIGHT as u32)
    }
}

impl<SPI, DC> DrawTarget for Ssd0323<SPI, DC> {
    type Color = Gray4;
    type Error = Infallible;

    /// A rectangle's rows byte by byte: two pixels a byte, and a lone nibble at either end.
    fn fill_solid(&mut self, area: &Rectangle, colour: Gray4) -> Result<(), Self::Error> {
        let area = area.intersection(&self.bounding_box());
        let Some(bottom_right) = area.bottom_right() else { return Ok(()) };
        let level = colour.luma() & 0x0F;
        let (first, last) = (area.top_left.x as usize, bottom_right.x as usize);
        for y in area.top_left.y as usize..=bottom_right.y as usize {
            let Some(row) = self.screen.get_mut(y) else { continue };
            for (index, byte) in row.iter_mut().enumerate().take(last / 2 + 1).skip(first / 2) {
                let (left, right) = (2 * index >= first, 2 * index < last);
                *byte = match (left, right) {
                    (true, true) => level << 4 | level,
                    (true, false) => (*byte & 0x0F) | (level << 4),
                    _ => (*byte & 0xF0) | level,
                };
            }
            self.dirty_rows |= 1u64 << y;
        }
        Ok(())
    }

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Self::Color>>,
    {
        for Pixel(point, colour) in pixels {
            let (Ok(x), Ok(y)) = (usize::try_from(point.x), usize::try_from(point.y)) else { continue };
            if x >= WIDTH || y >= HEIGHT {
                continue;
            }
            let Some(byte) = self.screen.get_mut(y).and_then(|row| row.get_mut(x / 2)) else { continue };
            let level = colour.luma() & 0x0F;
            *byte = if x % 2 == 0 { (*byte & 0x0F) | (level << 4) } else { (*byte & 0xF0) | level };
            self.dirty_rows |= 1u64 << y;
        }
        Ok(())
    }
}
