//! Peak stack use: cortex-m-rt's `paint-stack` feature fills everything between `_stack_end`
//! and `_stack_start` with `STACK_PAINT_VALUE` before `main`; the deepest word that no longer
//! holds it marks how far the stack grew (docs: shared/research/qemu.md, "Peak stack").

use cortex_m_rt::STACK_PAINT_VALUE;

extern "C" {
    /// Top of the stack (its initial value): flip-link sets it just below the lowest static.
    static _stack_start: u32;
    /// Lowest address the stack may reach: the start of RAM (flip-link; src/fault.rs).
    static _stack_end: u32;
}

/// Bytes of stack used so far, at the deepest point, and the stack's whole size.
pub fn peak_and_size() -> (u32, u32) {
    let top = core::ptr::addr_of!(_stack_start) as usize;
    let bottom = core::ptr::addr_of!(_stack_end) as usize;
    let mut address = bottom;
    while address < top {
        // SAFETY: every word between the two linker symbols is RAM reserved for the stack.
        let word = unsafe { core::ptr::read_volatile(address as *const u32) };
        if word != STACK_PAINT_VALUE {
            break;
        }
        address += 4;
    }
    ((top - address) as u32, (top - bottom) as u32)
}
