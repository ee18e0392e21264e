//! ARM MPS2 FPGA board with the AN386 image, QEMU machine `mps2-an386`: Cortex-M4F with a
//! single-precision FPU (cortex-m-rt enables it before `main`). No display: the picture goes
//! to the host as `framebuffer.bin` only. The memory layout (memory.x beside this file) uses
//! 256 KB of code and 64 KB of RAM of QEMU's 4 MB + 4 MB, to stand for a small part.

/// No display (driven) here: the picture goes to the host only.
pub use super::headless::{hold_picture_for_capture, init, Display};

/// The APB peripherals (UARTs, timers, the FPGA's registers), the MPU's region for them
/// (src/fault.rs); the firmware uses none, semihosting is all it needs.
pub const PERIPHERALS: (u32, u32) = (0x4000_0000, 1 << 20);

/// The stack the RAM check keeps at the least (src/ram.rs): the budget's 12 KB
/// (firmware/README.md, "Memory budget").
pub const STACK_BUDGET_BYTES: usize = 12 * 1024;

/// The frames below the shadow tables the RAM check counts (src/ram.rs): the common 4 KB.
pub const STACK_BASE_BYTES: usize = 4 * 1024;
