//! Faults end the run loudly: a message by semihosting naming what happened, and a failed exit
//! (QEMU exits with status 1), never a hang or a run that goes on with corrupted data.
//!
//! - **The memory layout** (flip-link, the linker of `.cargo/config.toml`): the stack is at the
//!   bottom of RAM, below `.data` and `.bss`, so a stack that overflows runs off the start of RAM
//!   instead of through the prepared scene.
//! - **The MPU** (src/mpu/, `mpu::protect_memory` first thing in `main`): only the board's flash (read,
//!   execute), its RAM (read, write) and its peripherals are accessible; everything else faults.
//!   So the stack running below RAM faults on its first word, and so does any access to an
//!   unmapped address, which the lm3s6965evb in QEMU otherwise ignores (writes dropped, reads 0:
//!   shared/research/qemu.md). That is how a stack overflow there used to hang: the render
//!   overwrote saved pointers with pixels (0x4444_4444) and went on writing through them.
//! - **The HardFault handler** (`HardFault` below, in assembly) moves the stack pointer off the
//!   faulting stack before any Rust code runs (an overflowed stack has no room for a handler;
//!   its frame would fault again and lock the core up), then `fault` reads the fault status
//!   registers and reports "stack overflow" or "hard fault at PC …: reason".
//!
//! MemManage, BusFault and UsageFault are not enabled, so each escalates to HardFault with its
//! status bits in CFSR. The MPU is off while HardFault runs (MPU_CTRL.HFNMIENA = 0).
//!
//! Per architecture (build.rs sets `cfg(armv6m)`, `cfg(armv7m)` or `cfg(armv8m)` from the
//! board): the ARMv7-M MPU (the M3 and M4F) takes a base and a power-of-two size per region
//! (RBAR, RASR); the ARMv8-M MPU (the M33) a base and an inclusive limit (RBAR, RLAR) with the
//! memory types in MAIR. The micro:bit's Cortex-M0 (ARMv6-M) has no MPU and no fault status
//! registers, only HardFault, whose handler there is Thumb-1: a stack overflow is still caught
//! when the access below RAM faults (QEMU's nRF51 faults on unmapped addresses, as the chip
//! does) and is recognised by the frame's place, but a stray access inside the memory map is
//! not stopped.

use core::ptr::addr_of;

use crate::decimal::Decimal;
use crate::semihosting::{self, print};

extern "C" {
    /// Top of the stack, its initial value (flip-link sets it to the lowest static's address).
    static _stack_start: u32;
    /// Bottom of the stack: the start of RAM (flip-link).
    static _stack_end: u32;
}

/// Room the handler needs below a frame it keeps in place.
const HANDLER_STACK_BYTES: u32 = 1024;

// The HardFault vector. r0 = the exception frame (the stack the fault was taken on), r1 =
// EXC_RETURN. When the frame lies in the stack with room below it, the handler's stack continues
// below the frame (which stays readable); otherwise (an overflow: the frame is below the stack's
// bottom, or too close to it) the handler takes the top of the stack: nothing returns from here,
// so what was there is no longer needed. Thumb-2 (ARMv7-M and ARMv8-M Mainline).
#[cfg(not(armv6m))]
core::arch::global_asm!(
    ".section .HardFault.user, \"ax\"",
    ".global HardFault",
    ".type HardFault, %function",
    ".thumb_func",
    "HardFault:",
    "  tst lr, #4",
    "  ite eq",
    "  mrseq r0, msp",
    "  mrsne r0, psp",
    "  mov r1, lr",
    "  ldr r2, =_stack_end",
    "  ldr r3, =_stack_start",
    "  add r2, r2, #{room}",
    "  cmp r0, r2",
    "  blo 1f",
    "  cmp r0, r3",
    "  bhi 1f",
    "  bic r2, r0, #7",
    "  mov sp, r2",
    "  b microtrace_fault",
    "1:",
    "  mov sp, r3",
    "  b microtrace_fault",
    ".size HardFault, . - HardFault",
    room = const HANDLER_STACK_BYTES,
);

// The same in Thumb-1 for ARMv6-M (the M0): no IT blocks or conditional MRS, 8-bit immediates,
// a branch of ±2 KB (so `bx` through a register to the handler's body).
#[cfg(armv6m)]
core::arch::global_asm!(
    ".section .HardFault.user, \"ax\"",
    ".global HardFault",
    ".type HardFault, %function",
    ".thumb_func",
    "HardFault:",
    "  mov r1, lr",
    "  movs r0, #4",
    "  tst r0, r1",
    "  bne 2f",
    "  mrs r0, msp",
    "  b 3f",
    "2:",
    "  mrs r0, psp",
    "3:",
    "  ldr r2, =_stack_end + {room}",
    "  ldr r3, =_stack_start",
    "  cmp r0, r2",
    "  blo 1f",
    "  cmp r0, r3",
    "  bhi 1f",
    "  lsrs r2, r0, #3",
    "  lsls r2, r2, #3",
    "  mov sp, r2",
    "  ldr r2, =microtrace_fault",
    "  bx r2",
    "1:",
    "  mov sp, r3",
    "  ldr r2, =microtrace_fault",
    "  bx r2",
    "  .ltorg",
    ".size HardFault, . - HardFault",
    room = const HANDLER_STACK_BYTES,
);

// Configurable Fault Status Register bits (ARMv7-M B3.2.15; ARMv8-M adds STKOF): MemManage,
// BusFault, UsageFault.
const MSTKERR: u32 = 1 << 4;
const STKERR: u32 = 1 << 12;
/// Each CFSR bit's meaning, for the message.
const CFSR_REASONS: [(u32, &str); 17] = [
    (1 << 0, "instruction fetch from an address outside the flash (MemManage)"),
    (1 << 1, "data access outside the flash, RAM and peripherals (MemManage)"),
    (1 << 3, "MemManage fault while unstacking"),
    (MSTKERR, "MemManage fault while stacking"),
    (1 << 5, "MemManage fault during lazy FPU state preservation"),
    (1 << 8, "instruction bus error"),
    (1 << 9, "precise data bus error"),
    (1 << 10, "imprecise data bus error"),
    (1 << 11, "bus fault while unstacking"),
    (STKERR, "bus fault while stacking"),
    (1 << 16, "undefined instruction (UsageFault)"),
    (1 << 17, "invalid state: a branch to an address without the Thumb bit (UsageFault)"),
    (1 << 18, "invalid exception return (UsageFault)"),
    (1 << 19, "coprocessor access: the FPU is off or absent (UsageFault)"),
    (1 << 20, "stack limit (UsageFault)"),
    (1 << 24, "unaligned access (UsageFault)"),
    (1 << 25, "division by zero (UsageFault)"),
];
const HFSR_VECTTBL: u32 = 1 << 1;

/// What the fault status registers say.
struct FaultStatus {
    cfsr: u32,
    hfsr: u32,
    /// The address that faulted, when MMFAR or BFAR holds it.
    address: Option<u32>,
}

/// The fault status registers (ARMv7-M and ARMv8-M Mainline).
#[cfg(not(armv6m))]
fn fault_status() -> Option<FaultStatus> {
    const MMARVALID: u32 = 1 << 7;
    const BFARVALID: u32 = 1 << 15;
    // SAFETY: the SCB's fault registers, read only.
    let scb = unsafe { &*cortex_m::peripheral::SCB::PTR };
    let cfsr = scb.cfsr.read();
    let address = if cfsr & MMARVALID != 0 {
        Some(scb.mmfar.read())
    } else if cfsr & BFARVALID != 0 {
        Some(scb.bfar.read())
    } else {
        None
    };
    Some(FaultStatus { cfsr, hfsr: scb.hfsr.read(), address })
}

/// ARMv6-M (the M0) has none: every fault is a HardFault that says no more.
#[cfg(armv6m)]
fn fault_status() -> Option<FaultStatus> {
    None
}

/// The HardFault handler's body, on a stack of its own (see `HardFault`).
#[no_mangle]
extern "C" fn microtrace_fault(frame: u32, _exc_return: u32) -> ! {
    let status = fault_status();
    let cfsr = status.as_ref().map_or(0, |status| status.cfsr);
    let fault_address = status.as_ref().and_then(|status| status.address);
    let bottom = addr_of!(_stack_end) as u32;
    let top = addr_of!(_stack_start) as u32;

    // Below the stack there is no RAM (flip-link), and the MPU faults on it: the stack ran off
    // its bottom when the fault was stacking, when the frame is below the bottom, or when the
    // access was just below it (a frame can be a few KB).
    let below_the_stack = |address: u32| address < bottom && address >= bottom.saturating_sub(64 * 1024);
    let overflow = cfsr & (MSTKERR | STKERR) != 0 || frame < bottom || fault_address.is_some_and(below_the_stack);
    if overflow {
        print("microtrace: stack overflow: the stack grew below its bottom, the start of RAM at ");
        print_hex(bottom);
        if let Some(address) = fault_address.filter(|address| below_the_stack(*address)) {
            print(" (an access at ");
            print_hex(address);
            print(")");
        }
        print("; it has ");
        print_grouped(top - bottom);
        print(" bytes, what the RAM leaves below the statics, which it cannot reach (flip-link): use a smaller framebuffer, fewer objects or a smaller number type\n");
        semihosting::exit(false)
    }

    print("microtrace: hard fault");
    // The frame is readable when it lies within the stack: its seventh word is the PC of the
    // instruction that faulted (for a precise fault).
    if frame >= bottom && frame.saturating_add(32) <= top {
        // SAFETY: eight words of RAM within the stack, the exception frame the core pushed.
        let pc = unsafe { core::ptr::read_volatile((frame + 24) as *const u32) };
        print(" at PC ");
        print_hex(pc);
    }
    print(": ");
    let Some(status) = status else {
        print("no fault status registers on ARMv6-M: a bus error (an access outside the memory map), an undefined instruction or an unaligned access\n");
        semihosting::exit(false)
    };
    let mut first = true;
    for (bit, reason) in CFSR_REASONS {
        if status.cfsr & bit != 0 {
            if !first {
                print(", ");
            }
            print(reason);
            first = false;
        }
    }
    if status.hfsr & HFSR_VECTTBL != 0 {
        print(if first { "" } else { ", " });
        print("bus fault reading the vector table");
        first = false;
    }
    if first {
        print("no fault status bit set");
    }
    if let Some(address) = fault_address {
        print(", at address ");
        print_hex(address);
    }
    print(" (CFSR ");
    print_hex(status.cfsr);
    print(", HFSR ");
    print_hex(status.hfsr);
    print(")\n");
    semihosting::exit(false)
}

/// `value` in decimal with its thousands separated by commas, as the build's messages write them
/// (src/ram.rs).
fn print_grouped(value: u32) {
    let digits = Decimal::new(u64::from(value));
    let text = digits.as_str();
    for (index, digit) in text.char_indices() {
        if index > 0 && (text.len() - index).is_multiple_of(3) {
            print(",");
        }
        print(text.get(index..index + digit.len_utf8()).unwrap_or("?"));
    }
}

/// `0x` and eight hex digits.
fn print_hex(value: u32) {
    let mut text = *b"0x00000000";
    for (index, digit) in text[2..].iter_mut().enumerate() {
        let nibble = (value >> (28 - 4 * index)) & 0xf;
        *digit = b"0123456789abcdef"[nibble as usize];
    }
    print(core::str::from_utf8(&text).unwrap_or("0x?"));
}

/// The fault test (`MICROTRACE_FAULT_TEST=1`, `cargo xtask firmware --provoke`): before the
/// scene is prepared, does what the host asks for by creating a file in QEMU's directory
/// (`provoke-panic`, `provoke-hard-fault`, `provoke-unexpected-interrupt`, `provoke-stack-overflow`).
#[cfg(microtrace_fault_test)]
pub fn provoke_if_asked() {
    use crate::semihosting::host_file_exists;
    if host_file_exists(b"provoke-panic\0") {
        panic!("provoked by the fault test (provoke-panic)");
    }
    if host_file_exists(b"provoke-hard-fault\0") {
        // The address the lm3s6965evb's silent hang wrote to: a pointer overwritten by pixels,
        // which the MPU stops. Without an MPU (the M0), that is the nRF51's peripheral space,
        // which takes the write; 0x6000_0000 is outside its memory map, a bus error.
        #[cfg(not(armv6m))]
        const ADDRESS: usize = 0x4444_4444;
        #[cfg(armv6m)]
        const ADDRESS: usize = 0x6000_0000;
        // SAFETY: none; this is the fault the test wants.
        unsafe { core::ptr::write_volatile(ADDRESS as *mut u32, 0) };
    }
    if host_file_exists(b"provoke-unexpected-interrupt\0") {
        // PendSV, which no handler of ours expects: main.rs's DefaultHandler.
        cortex_m::peripheral::SCB::set_pendsv();
        cortex_m::asm::isb();
    }
    if host_file_exists(b"provoke-stack-overflow\0") {
        let depth = descend(0);
        print(Decimal::new(u64::from(depth)).as_str());
    }
}

/// Recursion with a 256-byte frame until the stack runs out (it always does: the depth that
/// would end it is out of reach).
#[cfg(microtrace_fault_test)]
#[inline(never)]
fn descend(depth: u32) -> u32 {
    let mut frame = [depth; 64];
    core::hint::black_box(&mut frame);
    if core::hint::black_box(depth) == u32::MAX {
        return frame[0];
    }
    descend(depth + 1).wrapping_add(frame[63])
}
