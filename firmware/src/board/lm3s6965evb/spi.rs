//! SSI0 (an ARM PL022) and the GPIO lines the OLED needs, on the `embedded-hal` 1.0 traits: the
//! port is a [`SpiBus`], each line an [`OutputPin`], and [`SelectedDevice`] makes the bus and the
//! OLED's select line (PD0) a [`SpiDevice`]. The SSD0323 driver (`ssd0323.rs`) sees only the
//! traits, so it runs unchanged over any other board's HAL.

use core::convert::Infallible;

use embedded_hal::digital::{self, OutputPin};
use embedded_hal::spi::{self, Operation, SpiBus, SpiDevice};

use super::registers::{ssi0, sysctl, GpioPort, Register};

/// SSI0 as a master: 8-bit frames, SPI mode 3 (as the SSD0323 wants).
pub struct Ssi0 {
    _configured: (),
}

impl Ssi0 {
    /// Clocks SSI0 and its pins (port A: PA2 clock, PA3 frame, PA4 receive, PA5 transmit) and
    /// configures the port.
    pub fn new() -> Self {
        sysctl::RCGC1.set_bits(1 << 4);
        sysctl::RCGC2.set_bits(1 << 0);
        let ssi_pins = (1 << 2) | (1 << 3) | (1 << 4) | (1 << 5);
        GpioPort::A.alternate_function().set_bits(ssi_pins);
        GpioPort::A.digital_enable().set_bits(ssi_pins);
        ssi0::CR1.write(0); // disabled while configuring, master mode
        ssi0::CPSR.write(2); // QEMU ignores the clock; 2 is the smallest legal prescaler
        ssi0::CR0.write(ssi0::CR0_8BIT_MODE3);
        ssi0::CR1.write(ssi0::CR1_ENABLE);
        Self { _configured: () }
    }
}

/// Sends one byte and returns the byte clocked in. QEMU's PL022 stalls while its 8-entry
/// receive FIFO is full, so every byte's reply is read before the next (qemu.md, "PL022 quirk").
fn transfer(byte: u8) -> u8 {
    while ssi0::SR.read() & ssi0::SR_TNF == 0 {}
    ssi0::DR.write(u32::from(byte));
    while ssi0::SR.read() & ssi0::SR_RNE == 0 {}
    ssi0::DR.read() as u8
}

impl spi::ErrorType for Ssi0 {
    type Error = Infallible;
}

impl SpiBus<u8> for Ssi0 {
    fn read(&mut self, words: &mut [u8]) -> Result<(), Infallible> {
        words.iter_mut().for_each(|word| *word = transfer(0));
        Ok(())
    }

    fn write(&mut self, words: &[u8]) -> Result<(), Infallible> {
        words.iter().for_each(|word| {
            transfer(*word);
        });
        Ok(())
    }

    fn transfer(&mut self, read: &mut [u8], write: &[u8]) -> Result<(), Infallible> {
        for index in 0..read.len().max(write.len()) {
            let received = transfer(write.get(index).copied().unwrap_or(0));
            if let Some(word) = read.get_mut(index) {
                *word = received;
            }
        }
        Ok(())
    }

    fn transfer_in_place(&mut self, words: &mut [u8]) -> Result<(), Infallible> {
        words.iter_mut().for_each(|word| *word = transfer(*word));
        Ok(())
    }

    /// Waits until the last byte has left the port.
    fn flush(&mut self) -> Result<(), Infallible> {
        while ssi0::SR.read() & ssi0::SR_BSY != 0 {}
        Ok(())
    }
}

/// One GPIO line as a push-pull output.
pub struct GpioOutput {
    data: Register,
}

impl GpioOutput {
    /// Clocks `port` (`clock_bit` in RCGC2), drives line `pin` at `high` and then makes it an
    /// output, so it never glitches to the other level.
    pub fn new(port: GpioPort, clock_bit: u8, pin: u8, high: bool) -> Self {
        sysctl::RCGC2.set_bits(1 << clock_bit);
        let data = port.masked_data(1 << pin);
        data.write(if high { 0xFF } else { 0 });
        port.digital_enable().set_bits(1 << pin);
        port.direction().set_bits(1 << pin);
        Self { data }
    }
}

impl digital::ErrorType for GpioOutput {
    type Error = Infallible;
}

impl OutputPin for GpioOutput {
    fn set_low(&mut self) -> Result<(), Infallible> {
        self.data.write(0);
        Ok(())
    }

    fn set_high(&mut self) -> Result<(), Infallible> {
        self.data.write(0xFF);
        Ok(())
    }
}

/// PC7, the OLED's data/command line: low = command bytes, high = data bytes.
pub fn oled_data_command() -> GpioOutput {
    GpioOutput::new(GpioPort::C, 2, 7, false)
}

/// PD0, the OLED's select: high selects the OLED (QEMU's board muxes SSI0 between the OLED and
/// the SD card by it), active high where `embedded-hal-bus`'s devices assume an active-low
/// chip select.
pub fn oled_select() -> GpioOutput {
    GpioOutput::new(GpioPort::D, 3, 0, false)
}

/// A bus and the select line of one device on it, as an `embedded-hal` [`SpiDevice`]: the line
/// is driven high for each transaction, and low again once the bus has sent its last byte.
pub struct SelectedDevice<B, S> {
    bus: B,
    select: S,
}

impl<B, S> SelectedDevice<B, S> {
    pub fn new(bus: B, select: S) -> Self {
        Self { bus, select }
    }
}

/// A transaction's failure: the bus's or the select line's.
#[derive(Debug)]
pub enum DeviceError<B, S> {
    Bus(B),
    Select(S),
}

impl<B: spi::Error, S: core::fmt::Debug> spi::Error for DeviceError<B, S> {
    fn kind(&self) -> spi::ErrorKind {
        match self {
            DeviceError::Bus(error) => error.kind(),
            DeviceError::Select(_) => spi::ErrorKind::ChipSelectFault,
        }
    }
}

impl<B: SpiBus<u8>, S: OutputPin> spi::ErrorType for SelectedDevice<B, S> {
    type Error = DeviceError<B::Error, S::Error>;
}

impl<B: SpiBus<u8>, S: OutputPin> SpiDevice<u8> for SelectedDevice<B, S> {
    fn transaction(&mut self, operations: &mut [Operation<'_, u8>]) -> Result<(), Self::Error> {
        self.select.set_high().map_err(DeviceError::Select)?;
        for operation in operations {
            match operation {
                Operation::Read(words) => self.bus.read(words),
                Operation::Write(words) => self.bus.write(words),
                Operation::Transfer(read, write) => self.bus.transfer(read, write),
                Operation::TransferInPlace(words) => self.bus.transfer_in_place(words),
                Operation::DelayNs(nanoseconds) => {
                    // At most one cycle a nanosecond up to 1 GHz: long enough on any clock.
                    self.bus.flush().map(|()| cortex_m::asm::delay(*nanoseconds))
                }
            }
            .map_err(DeviceError::Bus)?;
        }
        self.bus.flush().map_err(DeviceError::Bus)?;
        self.select.set_low().map_err(DeviceError::Select)
    }
}
