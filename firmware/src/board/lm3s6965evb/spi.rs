//! Byte transfers on SSI0 (PL022) with the OLED's data/command line (PC7) and chip select
//! (PD0).

use super::registers::{ssi0, sysctl, GpioPort, Register};

/// PC7: low = command bytes, high = data bytes.
const DATA_COMMAND: Register = GpioPort::C.masked_data(1 << 7);
/// PD0: high selects the OLED (QEMU's board muxes SSI0 between the OLED and the SD card).
const OLED_SELECT: Register = GpioPort::D.masked_data(1 << 0);

/// SSI0 wired to the SSD0323, with the line state it last set.
pub struct OledSpi {
    sending_data: Option<bool>,
}

impl OledSpi {
    /// Clocks and configures SSI0 and the two GPIO lines.
    pub fn new() -> Self {
        // Port A (SSI0 pins PA2 clock, PA3 frame, PA5 transmit), C and D.
        sysctl::RCGC1.set_bits(1 << 4);
        sysctl::RCGC2.set_bits((1 << 0) | (1 << 2) | (1 << 3));
        let ssi_pins = (1 << 2) | (1 << 3) | (1 << 4) | (1 << 5);
        GpioPort::A.alternate_function().set_bits(ssi_pins);
        GpioPort::A.digital_enable().set_bits(ssi_pins);

        // Drive the levels before turning the pins into outputs, so they never glitch low.
        OLED_SELECT.write(0xFF);
        GpioPort::D.digital_enable().set_bits(1 << 0);
        GpioPort::D.direction().set_bits(1 << 0);
        GpioPort::C.digital_enable().set_bits(1 << 7);
        GpioPort::C.direction().set_bits(1 << 7);

        ssi0::CR1.write(0); // disabled while configuring, master mode
        ssi0::CPSR.write(2); // QEMU ignores the clock; 2 is the smallest legal prescaler
        ssi0::CR0.write(ssi0::CR0_8BIT_MODE3);
        ssi0::CR1.write(ssi0::CR1_ENABLE);
        Self { sending_data: None }
    }

    pub fn send_commands(&mut self, bytes: &[u8]) {
        self.set_mode(false);
        bytes.iter().for_each(|byte| transfer(*byte));
    }

    pub fn send_data(&mut self, bytes: &[u8]) {
        self.set_mode(true);
        bytes.iter().for_each(|byte| transfer(*byte));
    }

    fn set_mode(&mut self, data: bool) {
        if self.sending_data != Some(data) {
            // The D/C line is sampled with each byte: let the last one leave first.
            while ssi0::SR.read() & ssi0::SR_BSY != 0 {}
            DATA_COMMAND.write(if data { 0xFF } else { 0 });
            self.sending_data = Some(data);
        }
    }
}

/// Sends one byte and discards the byte clocked in. QEMU's PL022 stalls while its 8-entry
/// receive FIFO is full, so every byte's reply is read before the next (qemu.md, "PL022 quirk").
fn transfer(byte: u8) {
    while ssi0::SR.read() & ssi0::SR_TNF == 0 {}
    ssi0::DR.write(byte as u32);
    while ssi0::SR.read() & ssi0::SR_RNE == 0 {}
    let _ = ssi0::DR.read();
}
