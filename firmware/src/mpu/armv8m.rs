//! The ARMv8-M MPU (the M33): regions by base and inclusive limit, 32-byte granules, memory
//! types by index into MAIR (ARMv8-M Architecture Reference Manual, DDI 0553, B3.5 and D1.2).

use crate::scene;

/// The board's peripherals (src/board/mod.rs, `Board::PERIPHERALS`).
const PERIPHERALS: (u32, u32) = <crate::board::This as crate::board::Board>::PERIPHERALS;

// MPU_RBAR: SH (non-shareable 0b00) in bits 4:3, AP in 2:1, XN in 0.
const RBAR_EXECUTE_NEVER: u32 = 1;
const RBAR_READ_WRITE: u32 = 0b01 << 1;
const RBAR_READ_ONLY: u32 = 0b11 << 1;
// MPU_RLAR: AttrIndx in bits 3:1, EN in 0.
const RLAR_ENABLE: u32 = 1;
const RLAR_NORMAL: u32 = 0 << 1;
const RLAR_DEVICE: u32 = 1 << 1;
/// MAIR0: attribute 0 normal memory, write-through, read-allocate, non-transient, inner and
/// outer (0xAA); attribute 1 Device-nGnRE (0x04).
const MAIR0: u32 = 0xAA | (0x04 << 8);
// MPU_CTRL: on, with no background map for privileged code (PRIVDEFENA = 0), off in HardFault.
const CTRL_ENABLE: u32 = 1;

/// The regions the firmware may touch: (base, bytes, RBAR access bits, RLAR attribute bits).
/// The PPB (SCB, NVIC, MPU at 0xE000_0000) is always accessible, whatever the MPU says.
const REGIONS: [(u32, u32, u32, u32); 3] = [
    (scene::FLASH_ORIGIN, scene::FLASH_BYTES, RBAR_READ_ONLY, RLAR_NORMAL),
    (scene::RAM_ORIGIN, scene::RAM_BYTES, RBAR_READ_WRITE | RBAR_EXECUTE_NEVER, RLAR_NORMAL),
    (PERIPHERALS.0, PERIPHERALS.1, RBAR_READ_WRITE | RBAR_EXECUTE_NEVER, RLAR_DEVICE),
];

// A region starts and ends on a 32-byte granule.
const _: () = {
    let mut index = 0;
    while index < REGIONS.len() {
        let (base, bytes, _, _) = REGIONS[index];
        if bytes < 32 || base % 32 != 0 || bytes % 32 != 0 {
            panic!("memory.x: the flash, the RAM and the board's peripherals must each start and end on 32 bytes to be an MPU region (src/fault.rs)");
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
        mpu.mair[0].write(MAIR0);
        for (number, (base, bytes, access, attributes)) in REGIONS.iter().enumerate() {
            mpu.rnr.write(number as u32);
            mpu.rbar.write(base | access);
            mpu.rlar.write(((base + (bytes - 1)) & !0x1f) | attributes | RLAR_ENABLE);
        }
        mpu.ctrl.write(CTRL_ENABLE);
        cortex_m::asm::dsb();
        cortex_m::asm::isb();
    }
}
