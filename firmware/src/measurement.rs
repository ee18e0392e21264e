//! Markers for the instruction count. The QEMU TCG plugin that `cargo xtask firmware` builds
//! (xtask/src/instruction_count_plugin.c) counts the guest instructions executed from the first
//! instruction of `microtrace_measure_start` to the first of `microtrace_measure_end`; xtask finds
//! their addresses in the ELF (shared/research/qemu.md, "A TCG plugin").
//!
//! They are never inlined, their bodies differ so that the linker cannot fold them into one,
//! and each holds an `asm!` (through `cortex_m::asm::nop`) that the optimizer must treat as a
//! side effect: an empty body would let LLVM drop the calls altogether.

#[no_mangle]
#[inline(never)]
pub extern "C" fn microtrace_measure_start() {
    cortex_m::asm::nop();
}

#[no_mangle]
#[inline(never)]
pub extern "C" fn microtrace_measure_end() {
    cortex_m::asm::nop();
    cortex_m::asm::nop();
}
