// The QEMU boards the firmware runs on: their facts, written once. Read by firmware/build.rs
// (`include!`) and by xtask (`#[path]`, `xtask::firmware::Board`); a new board is a row here,
// a folder under src/board/ and a cargo feature (docs/architecture.md, "A new board").
// Plain Rust with no dependencies, so that both can compile it.

/// One board: what the build, the runner and the report need to know of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BoardFacts {
    /// Its name on the command line, and the firmware's cargo feature.
    pub name: &'static str,
    /// The rust target of its core.
    pub rust_target: &'static str,
    /// QEMU's machine and CPU.
    pub qemu_machine: &'static str,
    pub qemu_cpu: &'static str,
    /// Its core's architecture as the firmware's `cfg` names it (src/fault.rs: each has its
    /// own MPU, or none, and fault registers): `armv6m`, `armv7m` or `armv8m`.
    pub architecture: &'static str,
    /// Whether its FPU has a single-precision square root (`vsqrt.f32`, firmware/fpu-sqrt).
    pub fpu_square_root: bool,
    /// Its memory.x, from the firmware's folder.
    pub memory_x: &'static str,
    /// The display it drives and the picture captured from it, if it has one.
    pub display: BoardDisplay,
}

/// What a board shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BoardDisplay {
    /// Nothing: the picture goes to the host only.
    None,
    /// A render of any size (scaled or cut to the panel by its driver).
    AnySize,
    /// Only a render of exactly this size (width, height).
    Exactly(u16, u16),
}

/// The lm3s811evb's OLED: an SSD0303's 96x16 panel.
#[allow(dead_code)]
pub const LM3S811EVB_OLED: (u16, u16) = (96, 16);

/// Every board, in `xtask::firmware::Board`'s order.
pub const BOARDS: [BoardFacts; 6] = [
    BoardFacts { name: "lm3s6965evb", rust_target: "thumbv7m-none-eabi", qemu_machine: "lm3s6965evb", qemu_cpu: "cortex-m3", architecture: "armv7m", fpu_square_root: false, memory_x: "../memory.x", display: BoardDisplay::AnySize },
    BoardFacts { name: "mps2-an386", rust_target: "thumbv7em-none-eabihf", qemu_machine: "mps2-an386", qemu_cpu: "cortex-m4", architecture: "armv7m", fpu_square_root: true, memory_x: "src/board/mps2_an386/memory.x", display: BoardDisplay::None },
    BoardFacts { name: "microbit", rust_target: "thumbv6m-none-eabi", qemu_machine: "microbit", qemu_cpu: "cortex-m0", architecture: "armv6m", fpu_square_root: false, memory_x: "src/board/microbit/memory.x", display: BoardDisplay::None },
    BoardFacts { name: "mps2-an505", rust_target: "thumbv8m.main-none-eabihf", qemu_machine: "mps2-an505", qemu_cpu: "cortex-m33", architecture: "armv8m", fpu_square_root: true, memory_x: "src/board/mps2_an505/memory.x", display: BoardDisplay::None },
    BoardFacts { name: "lm3s811evb", rust_target: "thumbv7m-none-eabi", qemu_machine: "lm3s811evb", qemu_cpu: "cortex-m3", architecture: "armv7m", fpu_square_root: false, memory_x: "src/board/lm3s811evb/memory.x", display: BoardDisplay::Exactly(LM3S811EVB_OLED.0, LM3S811EVB_OLED.1) },
    BoardFacts { name: "netduinoplus2", rust_target: "thumbv7em-none-eabihf", qemu_machine: "netduinoplus2", qemu_cpu: "cortex-m4", architecture: "armv7m", fpu_square_root: true, memory_x: "src/board/netduinoplus2/memory.x", display: BoardDisplay::None },
];

/// The board named `name`.
#[allow(dead_code)]
pub fn board_named(name: &str) -> Option<&'static BoardFacts> {
    BOARDS.iter().find(|board| board.name == name)
}
