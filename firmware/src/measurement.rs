//! Markers for the instruction count. The QEMU TCG plugin that `cargo xtask firmware` builds
//! (xtask/src/instruction_count_plugin.c) notes the guest instructions executed when the first
//! instruction of each marker is first reached: the frame runs from `microtrace_measure_start`
//! (before the scene is prepared) to `microtrace_measure_end` (after the render), and
//! `microtrace_measure_render` (between the two) splits it into preparation and render. xtask
//! finds their addresses in the ELF (shared/research/qemu.md, "A TCG plugin").
//!
//! They are never inlined, their bodies differ (one, three and two `nop`s) so that the linker
//! cannot fold them into one, and each holds an `asm!` (through `cortex_m::asm::nop`) that the
//! optimizer must treat as a side effect: an empty body would let LLVM drop the calls altogether.

#[no_mangle]
#[inline(never)]
pub extern "C" fn microtrace_measure_start() {
    cortex_m::asm::nop();
}

#[no_mangle]
#[inline(never)]
pub extern "C" fn microtrace_measure_render() {
    cortex_m::asm::nop();
    cortex_m::asm::nop();
    cortex_m::asm::nop();
}

#[no_mangle]
#[inline(never)]
pub extern "C" fn microtrace_measure_end() {
    cortex_m::asm::nop();
    cortex_m::asm::nop();
}
