//! The firmware's memory budget on the lm3s6965evb (firmware/README.md, "Memory budget"), for
//! both thesis scenes in `f32`: the tests assert it and the report states it.

/// Flash (text + data), of the board's 256 KB.
pub const FLASH_BYTES: u64 = 96 * 1024;
/// Static RAM (data + bss): framebuffer, OLED copy, the prepared scene.
pub const STATIC_RAM_BYTES: u64 = 36 * 1024;
/// Peak stack.
pub const STACK_BYTES: u64 = 12 * 1024;
/// The board's RAM.
pub const RAM_BYTES: u64 = 64 * 1024;
/// What static RAM and stack within budget always leave free: a quarter of the RAM.
pub const FREE_RAM_BYTES: u64 = RAM_BYTES - STATIC_RAM_BYTES - STACK_BYTES;
