//! The only place this board's code touches memory-mapped registers. Addresses come from the
//! LM3S6965 data sheet and shared/research/qemu.md ("The lm3s6965evb OLED").

pub use crate::board::stellaris::{sysctl, GpioPort, Register};

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
