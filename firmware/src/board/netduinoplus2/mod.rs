//! Netduino Plus 2, QEMU machine `netduinoplus2`: an STM32F405RG, a Cortex-M4F with a
//! single-precision FPU (cortex-m-rt enables it before `main`). No display: the picture goes to
//! the host as `framebuffer.bin` only. The memory layout (memory.x beside this file) uses 256 KB
//! of the chip's 1 MB of flash (at 0x0800_0000, which the chip also maps at 0, where the core
//! reads its vector table) and 64 KB of its 128 KB of SRAM: the same budget as the other boards,
//! so their figures compare. Added by docs/architecture.md's "A new board" checklist alone.

/// No display (driven) here: the picture goes to the host only.
pub use super::headless::{hold_picture_for_capture, init, Display};

/// The APB and AHB1 peripherals (RCC, GPIO, the USARTs), the MPU's region for them
/// (src/fault.rs); the firmware uses none, semihosting is all it needs.
pub const PERIPHERALS: (u32, u32) = (0x4000_0000, 1 << 20);

/// The stack the RAM check keeps at the least (src/ram.rs): the budget's 12 KB
/// (firmware/README.md, "Memory budget").
pub const STACK_BUDGET_BYTES: usize = 12 * 1024;

/// The frames below the shadow tables the RAM check counts (src/ram.rs): the common 4 KB.
pub const STACK_BASE_BYTES: usize = 4 * 1024;
