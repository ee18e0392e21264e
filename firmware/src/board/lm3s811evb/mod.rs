//! Texas Instruments (Luminary Micro) EK-LM3S811 evaluation board, QEMU machine `lm3s811evb`:
//! a Cortex-M3 with **64 KB of flash and 8 KB of RAM** (memory.x beside this file), the
//! smallest part MicroTrace runs on. Its 96x16 OLED (an SSD0303 on I2C) is not driven yet: the
//! picture goes to the host as `framebuffer.bin`, streamed row by row, and the RAM it would
//! take stays with the stack.

/// No display (driven) here: the picture goes to the host only.
pub use super::headless::{hold_picture_for_capture, init};

/// The peripherals' region for the MPU (src/fault.rs): the first megabyte of the peripheral
/// region, as on the lm3s6965evb (the firmware touches none here but the system's).
pub const PERIPHERALS: (u32, u32) = (0x4000_0000, 1 << 20);

/// The stack the RAM check keeps at the least (src/ram.rs): 8 KB of RAM keeps snooker's
/// prepared scene (4,696 bytes in `f32`) and its deepest stack (3,072 bytes measured) with
/// 424 to spare, so 3 KB.
pub const STACK_BUDGET_BYTES: usize = 3 * 1024;

/// The frames below the shadow tables the RAM check counts (src/ram.rs): 1.5 KB, not the
/// other boards' 4 KB. Snooker in `f32` measured 3,072 bytes of peak stack with 21 objects'
/// tables (1,890 bytes as the check counts them) inside it, so its frames take at most
/// 1.2 KB; a scene that passes the check and still overflows stops with "stack overflow"
/// (src/fault.rs).
pub const STACK_BASE_BYTES: usize = 1536;
