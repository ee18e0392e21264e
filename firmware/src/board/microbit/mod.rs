//! BBC micro:bit (nRF51822, Cortex-M0: ARMv6-M, the RP2040's instruction set), QEMU machine
//! `microbit`: 256 KB of flash and 16 KB of RAM (memory.x beside this file), no FPU, no
//! hardware divide, no 32x32→64 multiply, and no MPU (src/fault.rs says what that changes).
//! Its 5x5 LED matrix is no display for a picture: the picture goes to the host as
//! `framebuffer.bin` only.

/// No display (driven) here: the picture goes to the host only.
pub use super::headless::{hold_picture_for_capture, init, Display};

/// No MPU on the M0: no region (src/fault.rs).
pub const PERIPHERALS: (u32, u32) = (0, 0);

/// The stack the RAM check keeps at the least (src/ram.rs): 16 KB of RAM cannot keep the
/// other boards' 12 KB beside a scene; snooker's deepest stack measured 4.5 KB in every number
/// type (docs/firmware-report.json), so 6 KB.
pub const STACK_BUDGET_BYTES: usize = 6 * 1024;

/// The frames below the shadow tables the RAM check counts (src/ram.rs): the common 4 KB.
pub const STACK_BASE_BYTES: usize = 4 * 1024;
