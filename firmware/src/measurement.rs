//! Markers for the instruction count. The QEMU TCG plugin that `cargo xtask firmware` builds
//! (xtask/src/instruction_count_plugin.c) counts the guest instructions executed from the first
//! instruction of `microtrace_measure_start` to the first of `microtrace_measure_end`; xtask finds
//! their addresses in the ELF. They are not inlined, and their bodies differ so that the linker
//! cannot fold them into one function.

use core::sync::atomic::{AtomicU32, Ordering};

/// Which phase the firmware is in (1 = measuring, 2 = done); also makes the markers differ.
static MEASURED_PHASE: AtomicU32 = AtomicU32::new(0);

#[no_mangle]
#[inline(never)]
pub extern "C" fn microtrace_measure_start() {
    MEASURED_PHASE.store(1, Ordering::SeqCst);
}

#[no_mangle]
#[inline(never)]
pub extern "C" fn microtrace_measure_end() {
    MEASURED_PHASE.store(2, Ordering::SeqCst);
}
