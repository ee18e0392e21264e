//! Board support: one folder per board, one board per build (a cargo feature). Each provides
//! `Display` (a `display::RowDisplay`: whole rows of grey levels), `init()`,
//! `hold_picture_for_capture()` (a board with no display it drives takes `headless`'s),
//! `STACK_BUDGET_BYTES` and `STACK_BASE_BYTES` (src/ram.rs), and with an MPU
//! `PERIPHERALS` (src/fault.rs); the render and the report are shared (main.rs).

//! build.rs checks that exactly one is enabled.

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
pub use lm3s6965evb::*;

#[cfg(feature = "mps2-an386")]
mod mps2_an386;
#[cfg(feature = "mps2-an386")]
pub use mps2_an386::*;

#[cfg(feature = "microbit")]
mod microbit;
#[cfg(feature = "microbit")]
pub use microbit::*;

#[cfg(feature = "mps2-an505")]
mod mps2_an505;
#[cfg(feature = "mps2-an505")]
pub use mps2_an505::*;

#[cfg(feature = "netduinoplus2")]
mod netduinoplus2;
#[cfg(feature = "netduinoplus2")]
pub use netduinoplus2::*;

#[cfg(feature = "lm3s811evb")]
mod lm3s811evb;
#[cfg(feature = "lm3s811evb")]
pub use lm3s811evb::*;
