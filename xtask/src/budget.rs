//! The firmware's memory budget on the lm3s6965evb (firmware/README.md, "Memory budget"), for
//! both thesis scenes in `f32`: the tests assert it and the report states it.

/// Flash (text + data), of the board's 256 KB: the lattice in `f32` measured 55,024 bytes
/// (80,028 while the prepared scene was an initialised static, its 10 to 15 KB stored in flash).
pub const FLASH_BYTES: u64 = 64 * 1024;
/// Initialised statics (`.data`, whose initial values take flash as well as RAM): none, in every
/// build the tests run. The prepared scene is a `static` whose every byte is zero
/// (`Scene::UNPREPARED`, so `.bss`).
pub const DATA_BYTES: u64 = 0;
/// Static RAM (data + bss): the prepared scene, its objects in flash and its grid's pool sized
/// by the entries the grid holds (the lattice in `f32` measured 10,592 bytes; 15,352 with the
/// objects copied into RAM, 23,992 with 24 grid entries an object, 36,288 with the framebuffer
/// and the OLED copy before the streamed render).
pub const STATIC_RAM_BYTES: u64 = 12 * 1024;
/// Peak stack.
pub const STACK_BYTES: u64 = 12 * 1024;
/// The board's RAM.
pub const RAM_BYTES: u64 = 64 * 1024;
/// What static RAM and stack within budget always leave free: 40 KB, 5/8 of the RAM.
pub const FREE_RAM_BYTES: u64 = RAM_BYTES - STATIC_RAM_BYTES - STACK_BYTES;
