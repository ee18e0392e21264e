//! What the two Stellaris boards share (the LM3S6965 and LM3S811 data sheets): their registers'
//! access, system control's clock gating, the GPIO ports, and holding the display's picture
//! until the host has captured it.

use crate::semihosting;

/// A 32-bit peripheral register at a fixed address of a Stellaris part.
#[derive(Clone, Copy)]
pub struct Register(usize);

impl Register {
    /// `address` must be a register of the part's peripheral space; only the boards' modules
    /// construct registers, from the constants here and beside them.
    pub const fn at(address: usize) -> Self {
        Self(address)
    }

    pub fn read(self) -> u32 {
        // SAFETY: a valid, aligned peripheral register (see `at`); reads have no side effects
        // beyond the peripheral's own (e.g. popping the SSI receive FIFO, which is intended).
        unsafe { core::ptr::read_volatile(self.0 as *const u32) }
    }

    pub fn write(self, value: u32) {
        // SAFETY: as for `read`; the firmware is single-threaded with no interrupts enabled.
        unsafe { core::ptr::write_volatile(self.0 as *mut u32, value) }
    }

    pub fn set_bits(self, mask: u32) {
        self.write(self.read() | mask);
    }
}

/// System control: run-mode clock gating.
pub mod sysctl {
    use super::Register;
    /// RCGC1: bit 4 clocks SSI0, bit 12 I2C0.
    pub const RCGC1: Register = Register::at(0x400F_E104);
    /// RCGC2: bit n clocks GPIO port n (A = 0).
    pub const RCGC2: Register = Register::at(0x400F_E108);
}

/// A PL061 GPIO port (Stellaris flavour, with the digital-enable and alternate-function
/// registers).
#[derive(Clone, Copy)]
pub struct GpioPort(usize);

// Each board uses its own ports and registers of these.
#[allow(dead_code)]
impl GpioPort {
    pub const A: Self = Self(0x4000_4000);
    pub const B: Self = Self(0x4000_5000);
    pub const C: Self = Self(0x4000_6000);
    pub const D: Self = Self(0x4000_7000);

    /// The data register that reads and writes only the pins in `mask`: PL061 masks data
    /// accesses by address bits [9:2].
    pub const fn masked_data(self, mask: u8) -> Register {
        Register::at(self.0 + ((mask as usize) << 2))
    }
    pub const fn direction(self) -> Register {
        Register::at(self.0 + 0x400)
    }
    pub const fn alternate_function(self) -> Register {
        Register::at(self.0 + 0x420)
    }
    pub const fn open_drain(self) -> Register {
        Register::at(self.0 + 0x50C)
    }
    pub const fn digital_enable(self) -> Register {
        Register::at(self.0 + 0x51C)
    }
}

/// Files that `cargo xtask firmware` uses to capture the screen before the firmware exits
/// (the picture disappears with QEMU): xtask creates the first before starting QEMU, and the
/// second once its monitor `screendump` has finished.
const CAPTURE_WANTED: &[u8] = b"screendump.wanted\0";
const CAPTURE_DONE: &[u8] = b"screendump.done\0";
/// How often to look for `CAPTURE_DONE` before giving up (each look is a semihosting call and a
/// short spin; xtask's timeout bounds the whole run anyway).
const CAPTURE_POLLS: u32 = 2_000_000;

/// Keeps the picture on the screen until the host has captured it, when a host asked for that.
pub fn hold_picture_for_capture() -> bool {
    if !semihosting::host_file_exists(CAPTURE_WANTED) {
        return true;
    }
    semihosting::print("microtrace: waiting for screendump\n");
    for _ in 0..CAPTURE_POLLS {
        if semihosting::host_file_exists(CAPTURE_DONE) {
            return true;
        }
        cortex_m::asm::delay(10_000);
    }
    semihosting::print("microtrace: no screendump came\n");
    false
}

