//! Texas Instruments (Luminary Micro) EK-LM3S6965 evaluation board, QEMU machine `lm3s6965evb`:
//! Cortex-M3, 256 KB flash, 64 KB RAM, and a 128x64 16-grey SSD0323 OLED on SSI0.

mod registers;
mod spi;
mod ssd0323;

pub use ssd0323::Ssd0323;

/// The display the render shows its rows on: the SSD0323 driver over this board's SSI0 (an
/// `embedded-hal` `SpiBus`) with the OLED's select line PD0 (a `SpiDevice`), and PC7 as its
/// data/command `OutputPin`.
pub type Display = Ssd0323<spi::SelectedDevice<spi::Ssi0, spi::GpioOutput>, spi::GpioOutput>;

/// Brings up the OLED, cleared (none if it does not answer).
pub fn init() -> Option<Display> {
    let device = spi::SelectedDevice::new(spi::Ssi0::new(), spi::oled_select());
    Ssd0323::new(device, spi::oled_data_command()).ok()
}

pub use super::stellaris::hold_picture_for_capture;

/// The peripherals the firmware touches (SSI0, GPIO C and D, system control) lie in the first
/// megabyte of the peripheral region: the MPU's region for them (src/fault.rs).
pub const PERIPHERALS: (u32, u32) = (0x4000_0000, 1 << 20);

/// The stack the RAM check keeps at the least (src/ram.rs): the budget's 12 KB
/// (firmware/README.md, "Memory budget").
pub const STACK_BUDGET_BYTES: usize = 12 * 1024;

/// The frames below the shadow tables the RAM check counts (src/ram.rs): the common 4 KB.
pub const STACK_BASE_BYTES: usize = 4 * 1024;
