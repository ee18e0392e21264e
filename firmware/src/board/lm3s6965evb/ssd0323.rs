//! An SSD0323 OLED controller over the `embedded-hal` 1.0 traits: any [`SpiDevice`] for the
//! bytes and any [`OutputPin`] for the data/command line (this board's SSI0 and PC7 are in
//! `spi.rs`; another board's HAL types fit as they are). The controller's own display RAM holds
//! the picture: the driver keeps no copy of it, and sends each row whole, as one command
//! transaction (the row's window) and one data transaction (its 64 bytes), when the render has
//! finished it (`RowDisplay`, src/display.rs). Pixel layout (qemu.md): two pixels per byte, high
//! nibble = left pixel, 64 bytes per row; 128x64 shown.

use embedded_hal::digital::OutputPin;
use embedded_hal::spi::SpiDevice;

use crate::display::RowDisplay;
use microtrace::model::Palette;

pub const WIDTH: usize = 128;
pub const HEIGHT: usize = 64;
const BYTES_PER_ROW: usize = WIDTH / 2;

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
    /// Rows that failed to send (a drawing error cannot be reported from inside the render).
    pub failed_rows: u16,
}

impl<SPI: SpiDevice<u8>, DC: OutputPin> Ssd0323<SPI, DC> {
    /// Initialises the controller and clears the screen, row by row.
    pub fn new(spi: SPI, data_command: DC) -> Result<Self, Error<SPI::Error, DC::Error>> {
        let mut display = Self { spi, data_command, sending_data: None, failed_rows: 0 };
        display.send(false, &INITIALISATION)?;
        for y in 0..HEIGHT {
            display.send_row(y, &[0; BYTES_PER_ROW])?;
        }
        Ok(display)
    }

    /// Sends row `y`: its window, then its 64 bytes (two pixels a byte, the left one high).
    pub fn send_row(&mut self, y: usize, row: &[u8; BYTES_PER_ROW]) -> Result<(), Error<SPI::Error, DC::Error>> {
        if y >= HEIGHT {
            return Ok(());
        }
        self.send(false, &[SET_COLUMN_WINDOW, 0, (BYTES_PER_ROW - 1) as u8, SET_ROW_WINDOW, y as u8, y as u8])?;
        self.send(true, row)
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

impl<SPI: SpiDevice<u8>, DC: OutputPin> RowDisplay for Ssd0323<SPI, DC> {
    /// Packs the row's grey levels (0..15, left to right; the first 128) two to a byte and sends
    /// the row; pixels beyond the levels given are black.
    fn show_row(&mut self, y: u16, indices: &[u8], palette: &Palette) {
        let mut row = [0u8; BYTES_PER_ROW];
        for (x, level) in crate::display::levels(palette, indices).take(WIDTH).enumerate() {
            if let Some(byte) = row.get_mut(x / 2) {
                *byte |= if x % 2 == 0 { (level & 0x0F) << 4 } else { level & 0x0F };
            }
        }
        if self.send_row(usize::from(y), &row).is_err() {
            self.failed_rows = self.failed_rows.saturating_add(1);
        }
    }
}
