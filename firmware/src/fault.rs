//! Faults end the run loudly: a message by semihosting naming what happened, and a failed exit
//! (QEMU exits with status 1), never a hang or a run that goes on with corrupted data.
//!
//! - **The memory layout** (flip-link, the linker of `.cargo/config.toml`): the stack is at the
//!   bottom of RAM, below `.data` and `.bss`, so a stack that overflows runs off the start of RAM
//!   instead of through the prepared scene.
//! - **The MPU** (`protect_memory`, first thing in `main`): only the board's flash (read,
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

use core::ptr::addr_of;

use crate::decimal::Decimal;
use crate::scene;
use crate::semihosting::{self, print};

extern "C" {
    /// Top of the stack, its initial value (flip-link sets it to the lowest static's address).
    static _stack_start: u32;
    /// Bottom of the stack: the start of RAM (flip-link).
    static _stack_end: u32;
}

// MPU_RASR fields (ARMv7-M Architecture Reference Manual, B3.5.9).
const RASR_ENABLE: u32 = 1;
const RASR_EXECUTE_NEVER: u32 = 1 << 28;
const RASR_FULL_ACCESS: u32 = 0b011 << 24;
const RASR_READ_ONLY: u32 = 0b110 << 24;
/// Normal memory, write-through (TEX 0, C 1, B 0).
const RASR_NORMAL: u32 = 1 << 17;
/// Shareable device memory (TEX 0, C 0, B 1, S 1).
const RASR_DEVICE: u32 = (1 << 16) | (1 << 18);
// MPU_CTRL: on, with no background map for privileged code (PRIVDEFENA = 0), off in HardFault.
const CTRL_ENABLE: u32 = 1;

/// The regions the firmware may touch: (base, bytes, attributes). The PPB (SCB, NVIC, MPU at
/// 0xE000_0000) is always accessible, whatever the MPU says.
const REGIONS: [(u32, u32, u32); 3] = [
    (scene::FLASH_ORIGIN, scene::FLASH_BYTES, RASR_READ_ONLY | RASR_NORMAL),
    (scene::RAM_ORIGIN, scene::RAM_BYTES, RASR_FULL_ACCESS | RASR_NORMAL | RASR_EXECUTE_NEVER),
    (crate::board::PERIPHERALS.0, crate::board::PERIPHERALS.1, RASR_FULL_ACCESS | RASR_DEVICE | RASR_EXECUTE_NEVER),
];

// An MPU region is a power of two of at least 32 bytes, aligned to its size: memory.x must
// describe its flash and RAM so (both boards' do: 256K at 0, 64K at 0x2000_0000).
const _: () = {
    let mut index = 0;
    while index < REGIONS.len() {
        let (base, bytes, _) = REGIONS[index];
        if !bytes.is_power_of_two() || bytes < 32 || base % bytes != 0 {
            panic!("memory.x: the flash, the RAM and the board's peripherals must each be a power of two of at least 32 bytes, aligned to its size, to be an MPU region (src/fault.rs)");
        }
        index += 1;
    }
};

/// Turns the MPU on with `REGIONS`: from here on, an access anywhere else faults.
pub fn protect_memory() {
    // SAFETY: the MPU's registers, written once before anything depends on the memory map; the
    // regions cover all the firmware touches (its code and constants, its RAM, the board's
    // peripherals).
    unsafe {
        let mpu = &*cortex_m::peripheral::MPU::PTR;
        if ((mpu._type.read() >> 8) & 0xff) < REGIONS.len() as u32 {
            crate::fail("the core has no MPU with 3 regions; the firmware relies on one to catch stack overflows");
        }
        for (number, (base, bytes, attributes)) in REGIONS.iter().enumerate() {
            mpu.rnr.write(number as u32);
            mpu.rbar.write(*base);
            mpu.rasr.write(((bytes.trailing_zeros() - 1) << 1) | attributes | RASR_ENABLE);
        }
        mpu.ctrl.write(CTRL_ENABLE);
        cortex_m::asm::dsb();
        cortex_m::asm::isb();
    }
}

/// Room the handler needs below a frame it keeps in place.
const HANDLER_STACK_BYTES: u32 = 1024;

// The HardFault vector. r0 = the exception frame (the stack the fault was taken on), r1 =
// EXC_RETURN. When the frame lies in the stack with room below it, the handler's stack continues
// below the frame (which stays readable); otherwise (an overflow: the frame is below the stack's
// bottom, or too close to it) the handler takes the top of the stack: nothing returns from here,
// so what was there is no longer needed.
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

// Configurable Fault Status Register bits (B3.2.15): MemManage, BusFault, UsageFault.
const IACCVIOL: u32 = 1 << 0;
const DACCVIOL: u32 = 1 << 1;
const MSTKERR: u32 = 1 << 4;
const MMARVALID: u32 = 1 << 7;
const STKERR: u32 = 1 << 12;
const BFARVALID: u32 = 1 << 15;
/// Each CFSR bit's meaning, for the message.
const CFSR_REASONS: [(u32, &str); 16] = [
    (IACCVIOL, "instruction fetch from an address outside the flash (MemManage)"),
    (DACCVIOL, "data access outside the flash, RAM and peripherals (MemManage)"),
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
    (1 << 24, "unaligned access (UsageFault)"),
    (1 << 25, "division by zero (UsageFault)"),
];
const HFSR_VECTTBL: u32 = 1 << 1;

/// The HardFault handler's body, on a stack of its own (see `HardFault`).
#[no_mangle]
extern "C" fn microtrace_fault(frame: u32, _exc_return: u32) -> ! {
    // SAFETY: the SCB's fault registers, read only.
    let scb = unsafe { &*cortex_m::peripheral::SCB::PTR };
    let cfsr = scb.cfsr.read();
    let hfsr = scb.hfsr.read();
    let mmfar = scb.mmfar.read();
    let bfar = scb.bfar.read();
    let bottom = addr_of!(_stack_end) as u32;
    let top = addr_of!(_stack_start) as u32;
    let fault_address = if cfsr & MMARVALID != 0 {
        Some(mmfar)
    } else if cfsr & BFARVALID != 0 {
        Some(bfar)
    } else {
        None
    };

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
        print(" bytes, what the RAM leaves below the statics, which it cannot reach (flip-link): use fewer objects or a smaller number type\n");
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
    let mut first = true;
    for (bit, reason) in CFSR_REASONS {
        if cfsr & bit != 0 {
            if !first {
                print(", ");
            }
            print(reason);
            first = false;
        }
    }
    if hfsr & HFSR_VECTTBL != 0 {
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
    print_hex(cfsr);
    print(", HFSR ");
    print_hex(hfsr);
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
        // The address the lm3s6965evb's silent hang wrote to: a pointer overwritten by pixels.
        // SAFETY: none; this is the fault the test wants. The MPU stops the write.
        unsafe { core::ptr::write_volatile(0x4444_4444 as *mut u32, 0) };
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
