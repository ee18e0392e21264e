//! The firmware's memory budget on the lm3s6965evb (firmware/README.md, "Memory budget"), for
//! both thesis scenes in `f32`: the tests assert it and the report states it.

/// Flash (text + data), of the board's 256 KB.
pub const FLASH_BYTES: u64 = 96 * 1024;
/// Static RAM (data + bss): the prepared scene (no framebuffer and no OLED copy since the
/// streamed render: the lattice in `f32` measured 23,992 bytes, 36,288 before).
pub const STATIC_RAM_BYTES: u64 = 24 * 1024;
/// Peak stack.
pub const STACK_BYTES: u64 = 12 * 1024;
/// The board's RAM.
pub const RAM_BYTES: u64 = 64 * 1024;
/// What static RAM and stack within budget always leave free: 28 KB, 7/16 of the RAM.
pub const FREE_RAM_BYTES: u64 = RAM_BYTES - STATIC_RAM_BYTES - STACK_BYTES;
