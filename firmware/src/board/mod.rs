//! Board support: one folder per board, one board per build (a cargo feature; build.rs checks
//! that exactly one is enabled, and firmware/boards.rs holds each board's facts). What a board's
//! module must provide is the [`Board`] trait's items, which [`This`] takes from the module the
//! build selected: a board that lacks one does not compile, naming it. The render and the report
//! are shared (main.rs).

/// What a board without a display it drives provides: no display, nothing to capture.
#[cfg(not(any(feature = "lm3s6965evb", feature = "lm3s811evb")))]
mod headless {
    /// The type is there so the shared code has one to name.
    pub type Display = crate::display::NoDisplay;

    pub fn init() -> Option<Display> {
        None
    }

    /// Nothing to capture.
    pub fn hold_picture_for_capture() -> bool {
        true
    }
}

#[cfg(any(feature = "lm3s6965evb", feature = "lm3s811evb"))]
mod stellaris;

#[cfg(feature = "lm3s6965evb")]
mod lm3s6965evb;
#[cfg(feature = "lm3s6965evb")]
use lm3s6965evb as selected;

#[cfg(feature = "mps2-an386")]
mod mps2_an386;
#[cfg(feature = "mps2-an386")]
use mps2_an386 as selected;

#[cfg(feature = "microbit")]
mod microbit;
#[cfg(feature = "microbit")]
use microbit as selected;

#[cfg(feature = "mps2-an505")]
mod mps2_an505;
#[cfg(feature = "mps2-an505")]
use mps2_an505 as selected;

#[cfg(feature = "netduinoplus2")]
mod netduinoplus2;
#[cfg(feature = "netduinoplus2")]
use netduinoplus2 as selected;

#[cfg(feature = "lm3s811evb")]
mod lm3s811evb;
#[cfg(feature = "lm3s811evb")]
use lm3s811evb as selected;

/// What the shared firmware (main.rs, ram.rs, mpu/) needs of a board.
pub trait Board {
    /// The display it shows rows on (`display::NoDisplay` for a board without one).
    type Display: crate::display::RowDisplay;
    /// The stack the RAM check keeps at the least (src/ram.rs; firmware/README.md, "Memory
    /// budget").
    const STACK_BUDGET_BYTES: usize;
    /// The frames below the shadow tables the RAM check counts (src/ram.rs).
    const STACK_BASE_BYTES: usize;
    /// The peripherals the firmware touches, (address, bytes): the MPU's device region
    /// (src/mpu/; unused on a core without an MPU).
    #[cfg_attr(armv6m, allow(dead_code))]
    const PERIPHERALS: (u32, u32);
    /// Starts the board: its display, cleared, if it drives one (and it answers).
    fn init() -> Option<Self::Display>;
    /// Keeps the picture shown until the host has captured it, when a host asked for that;
    /// whether it was (a board without a display: at once).
    fn hold_picture_for_capture() -> bool;
}

/// The board this build is for: its module's items, through [`Board`].
pub struct This;

impl Board for This {
    type Display = selected::Display;
    const STACK_BUDGET_BYTES: usize = selected::STACK_BUDGET_BYTES;
    const STACK_BASE_BYTES: usize = selected::STACK_BASE_BYTES;
    const PERIPHERALS: (u32, u32) = selected::PERIPHERALS;

    fn init() -> Option<Self::Display> {
        selected::init()
    }

    fn hold_picture_for_capture() -> bool {
        selected::hold_picture_for_capture()
    }
}
