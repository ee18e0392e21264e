//! The only place this board's code touches memory-mapped registers. Addresses come from the
//! LM3S6965 data sheet and shared/research/qemu.md ("The lm3s6965evb OLED").

/// A 32-bit peripheral register at a fixed address of this board.
#[derive(Clone, Copy)]
pub struct Register(usize);

impl Register {
    /// `address` must be a register of the LM3S6965's peripheral space; only this board's
    /// modules construct registers, from the constants below.
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
    /// RCGC1: bit 4 clocks SSI0.
    pub const RCGC1: Register = Register::at(0x400F_E104);
    /// RCGC2: bit n clocks GPIO port n (A = 0).
    pub const RCGC2: Register = Register::at(0x400F_E108);
}

/// A PL061 GPIO port (Stellaris flavour, with the digital-enable and alternate-function
/// registers).
#[derive(Clone, Copy)]
pub struct GpioPort(usize);

impl GpioPort {
    pub const A: Self = Self(0x4000_4000);
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
    pub const fn digital_enable(self) -> Register {
        Register::at(self.0 + 0x51C)
    }
}

/// SSI0, an ARM PL022.
pub mod ssi0 {
    use super::Register;
    const BASE: usize = 0x4000_8000;
    pub const CR0: Register = Register::at(BASE);
    pub const CR1: Register = Register::at(BASE + 0x04);
    pub const DR: Register = Register::at(BASE + 0x08);
    pub const SR: Register = Register::at(BASE + 0x0C);
    pub const CPSR: Register = Register::at(BASE + 0x10);

    /// CR0: 8-bit frames, Motorola SPI mode 3 (SPO = SPH = 1) as the SSD0323 wants.
    pub const CR0_8BIT_MODE3: u32 = 0x07 | (1 << 6) | (1 << 7);
    /// CR1.SSE: port enable.
    pub const CR1_ENABLE: u32 = 1 << 1;
    /// SR: transmit FIFO not full, receive FIFO not empty, busy.
    pub const SR_TNF: u32 = 1 << 1;
    pub const SR_RNE: u32 = 1 << 2;
    pub const SR_BSY: u32 = 1 << 4;
}
