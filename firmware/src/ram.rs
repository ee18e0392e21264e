//! Does the scene fit the chip's RAM? Checked at compile time, in the target's own layout, before
//! the linker runs: a scene too large fails the build with a message naming the scene, what it
//! needs and what the board has, e.g.
//!
//! ```text
//! error[E0080]: evaluation panicked: /…/many-340.mts: needs 71,224 bytes of RAM (the prepared
//! scene 36,528 for 340 objects in f32, framebuffer 0 for 128x64, stack reserve 34,696), the
//! lm3s6965evb has 65,536 (firmware/README.md, "When it fails")
//! ```
//!
//! instead of rust-lld's `section '.bss' will not fit in region 'RAM'` (or, worse, a build that
//! links and then runs its stack through the statics). The static RAM counted is the prepared
//! scene (`size_of` of `Scene<Number, OBJECT_COUNT>` as compiled for the chip) and the
//! framebuffer: none in the streamed build (each row goes to the host and the display as it is
//! done, from a row on the stack: src/display.rs), 8 KB with the `framebuffer` or `progressive`
//! feature. The display keeps no copy (the SSD0323 has its own display RAM). The few bytes of
//! other statics fit in the stack reserve.
//!
//! The stack reserve grows with the scene: the render's shadow tables take a light's chord and
//! blocker set per object (and, while they are built, the sweep's reach and order; each light
//! after the first its own chord and blocker set), on top of preparing's and the pixel's frames
//! (4 KB; 1.5 KB on the 8 KB lm3s811evb: the board's `STACK_BASE_BYTES`). It is that, but at
//! least the board's budget of peak stack (firmware/README.md, "Memory budget": 12 KB; 6 KB on
//! the micro:bit, 3 KB on the lm3s811evb), or `MICROTRACE_STACK_RESERVE` (build.rs) when given. Since the objects left
//! the RAM, the stack is what limits a large scene: 300 spheres measured 32,448 bytes of
//! prepared scene and 27,760 of peak stack in `f32`. A scene that passes this check and still
//! overflows its stack stops with "stack overflow" (src/fault.rs), never silently.

use core::mem::size_of;

use microtrace::config::Config;
use microtrace::optimize::shadow_culling::{BlockerSet, DirectionChord, LightReach, ShadowTables};
use microtrace::storage::Table;

use crate::scene;

/// Whether the scene's hierarchy of boxes is baked (its shadow rays' blockers are found by it:
/// the render builds no shadow tables).
const HIERARCHY_IN_FLASH: bool = <<scene::SceneConfig as Config>::Hierarchy<u16> as Table<u16>>::BAKED;
/// Whether the lights' shadow tables are baked (the render builds none).
const SHADOW_TABLES_IN_FLASH: bool = <<scene::SceneConfig as Config>::LightTables<ShadowTables<'static, scene::Number>> as Table<_>>::BAKED;
/// The grid's pool entries per object built on the chip (none: a baked grid is in flash).
const GRID_ENTRIES_PER_OBJECT: usize = <scene::SceneConfig as Config>::GRID_ENTRIES_PER_OBJECT;

/// The stack the render's shadow tables take per object, or preparation's tables when none are
/// built: a hierarchy in flash finds the shadow rays' blockers instead, or the tables
/// themselves are in flash.
const TABLES_PER_OBJECT: usize = if HIERARCHY_IN_FLASH || SHADOW_TABLES_IN_FLASH { PREPARATION_PER_OBJECT } else { SHADOW_TABLES_PER_OBJECT };

/// Preparation's tables per object on the stack when the chip builds its tables
/// (optimize/acceleration.rs, `rebuild_with`: each object's screen capsule and primitive;
/// optimize/grid.rs: its places in the grid's pool), twice: once is less than measured (tree-s6
/// in `f32`, 40 bytes an object once, its peak 60 an object above the base), as a table made
/// and then moved can be live twice. None for a baked scene, whose grid and view's tables are
/// in flash (`GRID_ENTRIES_PER_OBJECT` 0): `rebuild_with` is not even linked.
const PREPARATION_PER_OBJECT: usize = if GRID_ENTRIES_PER_OBJECT == 0 {
    0
} else {
    2 * (size_of::<microtrace::optimize::capsule::Capsule<scene::Number>>() + size_of::<microtrace::model::Primitive>() + GRID_ENTRIES_PER_OBJECT * size_of::<u16>())
};

/// The shadow tables per object (render/shadow_tables.rs: `with_shadow_culling`,
/// `build_shadow_tables`, and for a scene with several lights `with_more_lights_culling`, whose
/// tables hold the scene's other lights).
const SHADOW_TABLES_PER_OBJECT: usize = size_of::<DirectionChord<scene::Number>>()
    + size_of::<BlockerSet>()
    + size_of::<LightReach<scene::Number>>()
    + size_of::<u16>()
    + scene::OTHER_LIGHTS * (size_of::<DirectionChord<scene::Number>>() + size_of::<BlockerSet>());

/// The frames below the tables: preparing's, the row's and the pixel's (the report's deepest
/// stack beyond the tables is about 3 KB): 4 KB, less on a board whose RAM cannot spare it.
const STACK_BASE_BYTES: usize = <crate::board::This as crate::board::Board>::STACK_BASE_BYTES;

/// The budget's peak stack: the least the check keeps (12 KB; 6 KB on the 16 KB micro:bit, 3 KB
/// on the 8 KB lm3s811evb).
const STACK_BUDGET_BYTES: usize = <crate::board::This as crate::board::Board>::STACK_BUDGET_BYTES;

/// The stack this build keeps free for preparing and rendering (see the module's comment).
pub const STACK_RESERVE_BYTES: usize = match scene::STACK_RESERVE_BYTES {
    Some(bytes) => bytes,
    None => {
        let tables = STACK_BASE_BYTES + scene::OBJECT_COUNT * TABLES_PER_OBJECT;
        if tables > STACK_BUDGET_BYTES { tables } else { STACK_BUDGET_BYTES }
    }
};

/// The static RAM the scene takes: the prepared scene and the framebuffer (none when streamed).
pub const SCENE_BYTES: usize = core::mem::size_of::<crate::PreparedScene>();
#[cfg(any(feature = "framebuffer", feature = "progressive"))]
pub const FRAMEBUFFER_BYTES: usize = scene::PIXEL_COUNT;
#[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
pub const FRAMEBUFFER_BYTES: usize = 0;
pub const NEEDED_BYTES: usize = SCENE_BYTES + FRAMEBUFFER_BYTES + STACK_RESERVE_BYTES;

const _: () = {
    if NEEDED_BYTES > scene::RAM_BYTES as usize {
        panic!("{}", TOO_LARGE.as_str());
    }
};

/// A sizing build (build.rs's `size_only`: more objects than it bakes) that fits the
/// RAM stops here, saying so; one that does not stopped above with what it needs.
#[cfg(microtrace_sizing)]
const _: () = {
    if NEEDED_BYTES <= scene::RAM_BYTES as usize {
        panic!("{}", FITS_BUT_NOT_PREPARED.as_str());
    }
};

#[cfg(microtrace_sizing)]
const FITS_BUT_NOT_PREPARED: Text = Text::new()
    .text(scene::SCENE_PATH)
    .text(": ")
    .number(scene::OBJECT_COUNT)
    .text(" objects fit the RAM (")
    .number(NEEDED_BYTES)
    .text(" bytes) but the build bakes at most ")
    .number(scene::PREPARED_AHEAD_AT_MOST)
    .text(" (microtrace::bake::BAKE_CAPACITY)");

/// The message, written at compile time (a `const` panic takes a `&str`, not a format).
const TOO_LARGE: Text = Text::new()
    .text(scene::SCENE_PATH)
    .text(": needs ")
    .number(NEEDED_BYTES)
    .text(" bytes of RAM (the prepared scene ")
    .number(SCENE_BYTES)
    .text(" for ")
    .number(scene::OBJECT_COUNT)
    .text(" objects in ")
    .text(scene::NUMBER_NAME)
    .text(", framebuffer ")
    .number(FRAMEBUFFER_BYTES)
    .text(" for ")
    .number(scene::WIDTH as usize)
    .text("x")
    .number(scene::HEIGHT as usize)
    .text(", stack reserve ")
    .number(STACK_RESERVE_BYTES)
    .text("), the ")
    .text(scene::BOARD_NAME)
    .text(" has ")
    .number(scene::RAM_BYTES as usize)
    .text(" (firmware/README.md, \"When it fails\")");

/// Text built by `const fn`s: at most `CAPACITY` bytes (more is cut off).
struct Text {
    bytes: [u8; Text::CAPACITY],
    length: usize,
}

impl Text {
    const CAPACITY: usize = 1024;

    const fn new() -> Self {
        Self { bytes: [0; Self::CAPACITY], length: 0 }
    }

    const fn text(mut self, text: &str) -> Self {
        let bytes = text.as_bytes();
        let mut index = 0;
        while index < bytes.len() && self.length < Self::CAPACITY {
            self.bytes[self.length] = bytes[index];
            self.length += 1;
            index += 1;
        }
        self
    }

    /// `value` in decimal, thousands separated by commas (65,536).
    const fn number(mut self, value: usize) -> Self {
        let mut digits = [0u8; 32];
        let mut count = 0;
        let mut rest = value;
        loop {
            if count % 4 == 3 {
                digits[count] = b',';
                count += 1;
            }
            digits[count] = b'0' + (rest % 10) as u8;
            count += 1;
            rest /= 10;
            if rest == 0 {
                break;
            }
        }
        while count > 0 && self.length < Self::CAPACITY {
            count -= 1;
            self.bytes[self.length] = digits[count];
            self.length += 1;
        }
        self
    }

    const fn as_str(&self) -> &str {
        let (text, _) = self.bytes.split_at(self.length);
        match core::str::from_utf8(text) {
            Ok(text) => text,
            // Only reached if a cut fell inside a UTF-8 sequence of the scene's path.
            Err(_) => "the scene needs more RAM than the board has (its path is not valid UTF-8)",
        }
    }
}
