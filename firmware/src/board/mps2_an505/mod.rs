//! ARM MPS2 FPGA board with the AN505 image, QEMU machine `mps2-an505`: Cortex-M33 (ARMv8-M
//! Mainline, the RP2350's core) with a single-precision FPU (cortex-m-rt enables it before
//! `main`), running Secure, where it starts. No display: the picture goes to the host as
//! `framebuffer.bin` only. The memory layout (memory.x beside this file) uses 256 KB of code
//! and 64 KB of RAM, to stand for a small part.

/// No display (driven) here: the picture goes to the host only.
pub use super::headless::{hold_picture_for_capture, init, Display};

/// The Secure alias of the APB peripherals, the MPU's region for them (src/fault.rs); the
/// firmware uses none, semihosting is all it needs.
pub const PERIPHERALS: (u32, u32) = (0x5000_0000, 1 << 20);

/// The stack the RAM check keeps at the least (src/ram.rs): the budget's 12 KB.
pub const STACK_BUDGET_BYTES: usize = 12 * 1024;

/// The frames below the shadow tables the RAM check counts (src/ram.rs): the common 4 KB.
pub const STACK_BASE_BYTES: usize = 4 * 1024;
