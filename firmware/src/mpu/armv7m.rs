//! The ARMv7-M MPU (the M3 and M4F).

use crate::scene;

/// The board's peripherals (src/board/mod.rs, `Board::PERIPHERALS`).
const PERIPHERALS: (u32, u32) = <crate::board::This as crate::board::Board>::PERIPHERALS;

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
    (PERIPHERALS.0, PERIPHERALS.1, RASR_FULL_ACCESS | RASR_DEVICE | RASR_EXECUTE_NEVER),
];

// An MPU region is a power of two of at least 32 bytes, aligned to its size: memory.x must
// describe its flash and RAM so (every ARMv7-M board's does: 256K or 64K at 0, 64K or 8K at
// 0x2000_0000).
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
