//! Texas Instruments (Luminary Micro) EK-LM3S811 evaluation board, QEMU machine `lm3s811evb`:
//! a Cortex-M3 with **64 KB of flash and 8 KB of RAM** (memory.x beside this file), the
//! smallest part MicroTrace runs on, with a 96x16 OLED (an SSD0303 on I2C0, `ssd0303.rs`). A
//! render of the panel's size (`--size 96x16`) is shown on it as well as streamed to the host;
//! a larger one (the 128x64 of the other boards) goes to the host only, and links no driver (at
//! 96x16 it took 808 bytes more stack: a page of dots, a row of diffusion errors, the bus).

mod i2c;
mod ssd0303;

use crate::display::{NoDisplay, RowDisplay};

pub use super::stellaris::hold_picture_for_capture;

/// Whether the render is the panel's size: then the OLED is driven (chosen at compile time, so
/// a larger render links no driver and keeps no page).
const SHOWN: bool = crate::scene::WIDTH as usize == ssd0303::WIDTH && crate::scene::HEIGHT as usize == ssd0303::HEIGHT;

/// The display, by [`SHOWN`]: the SSD0303 over I2C0, or none.
pub type Display = <Panel<SHOWN> as Choice>::Display;

/// Brings up the OLED, cleared (none if it does not answer, or the render is not its size).
pub fn init() -> Option<Display> {
    <Panel<SHOWN> as Choice>::init()
}

/// The display chosen by whether the render is the panel's size.
pub struct Panel<const SHOWN: bool>;

pub trait Choice {
    type Display: RowDisplay;
    fn init() -> Option<Self::Display>;
}

impl Choice for Panel<true> {
    type Display = ssd0303::Ssd0303<i2c::I2c0>;

    fn init() -> Option<Self::Display> {
        ssd0303::Ssd0303::new(i2c::I2c0::new()).ok()
    }
}

impl Choice for Panel<false> {
    type Display = NoDisplay;

    fn init() -> Option<Self::Display> {
        None
    }
}

/// The peripherals' region for the MPU (src/fault.rs): the first megabyte of the peripheral
/// region, as on the lm3s6965evb (I2C0, GPIO port B and the system control).
pub const PERIPHERALS: (u32, u32) = (0x4000_0000, 1 << 20);

/// The stack the RAM check keeps at the least (src/ram.rs), measured in `f32` with the view's
/// tables, the shadow tables and the grid in flash (nothing on the stack grows with the
/// objects): streamed to the host, snooker's deepest stack is 1,872 bytes and the lattice's
/// 2,136, so 2.5 KB; shown on the OLED ([`SHOWN`]: the page and the error diffusion's row too)
/// snooker's is 2,608 and the lattice's 2,920, so 3 KB.
pub const STACK_BUDGET_BYTES: usize = if SHOWN { 3 * 1024 } else { 2560 };

/// The frames below the shadow tables the RAM check counts (src/ram.rs): 1.5 KB, not the
/// other boards' 4 KB. Snooker in `f32` measured 3,072 bytes of peak stack with 21 objects'
/// tables (1,890 bytes as the check counts them) inside it, so its frames take at most
/// 1.2 KB; a scene that passes the check and still overflows stops with "stack overflow"
/// (src/fault.rs).
pub const STACK_BASE_BYTES: usize = 1536;
