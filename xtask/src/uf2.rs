//! UF2 files: what a user drags onto a Raspberry Pi Pico held in BOOTSEL mode (the RP2040
//! datasheet, §2.8.4.2, "UF2 format details"; Microsoft's UF2 specification). A file is a run of
//! 512-byte blocks, each a 32-byte header (two magic numbers, flags, the target address, the
//! payload's size, the block's number, the number of blocks, the family ID), up to 476 bytes of
//! payload and a closing magic number. The RP2040's boot ROM takes only 256-byte payloads at
//! 256-byte boundaries of its flash, with the family ID flag and the RP2040's family.

use std::ops::Range;

/// The RP2040's UF2 family ID.
pub const RP2040_FAMILY: u32 = 0xe48b_ff56;
/// The RP2350's family for an image for its Arm cores in the Secure state ("rp2350-arm-s" in
/// the UF2 specification's uf2families.json, as picotool writes it).
pub const RP2350_ARM_SECURE_FAMILY: u32 = 0xe48b_ff59;
/// A block's size in the file.
pub const BLOCK_BYTES: usize = 512;
/// The payload of each block the RP2040 takes: one flash page.
pub const PAYLOAD_BYTES: usize = 256;

const MAGIC_START0: u32 = 0x0a32_4655;
const MAGIC_START1: u32 = 0x9e5d_5157;
const MAGIC_END: u32 = 0x0ab1_6f30;
/// The header's family-ID field holds a family (else it is the file's size).
const FLAG_FAMILY_ID: u32 = 0x0000_2000;
const PT_LOAD: u32 = 1;

/// The bytes an ELF32 (little-endian) stores: each loadable segment's file contents at its
/// physical (load) address, so that `.data`'s initial values are where the image copies them
/// from.
pub fn loadable(elf: &[u8]) -> Result<Vec<(u64, Vec<u8>)>, String> {
    let u16_at = |at: usize| elf.get(at..at + 2).map(|b| u16::from_le_bytes([b[0], b[1]]));
    let u32_at = |at: usize| elf.get(at..at + 4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
    if elf.get(..6) != Some(&[0x7f, b'E', b'L', b'F', 1, 1][..]) {
        return Err("not a little-endian ELF32 file".into());
    }
    let truncated = || "the ELF's program headers are cut short".to_string();
    let (table, size, count) = (u32_at(28).ok_or_else(truncated)?, u16_at(42).ok_or_else(truncated)?, u16_at(44).ok_or_else(truncated)?);
    let mut segments = Vec::new();
    for index in 0..usize::from(count) {
        let header = table as usize + index * usize::from(size);
        let field = |offset: usize| u32_at(header + offset).ok_or_else(truncated);
        let (kind, offset, physical, file_size) = (field(0)?, field(4)?, field(12)?, field(16)?);
        if kind != PT_LOAD || file_size == 0 {
            continue;
        }
        let bytes = elf.get(offset as usize..offset as usize + file_size as usize).ok_or_else(|| format!("segment {index}'s bytes are past the ELF's end"))?;
        segments.push((u64::from(physical), bytes.to_vec()));
    }
    Ok(segments)
}

/// The UF2 file that writes `elf`'s loadable bytes, all of which must lie in `flash`: one block
/// for each 256-byte page they touch, in address order, the rest of a page zero (as the Pico
/// SDK's elf2uf2 does).
pub fn from_elf(elf: &[u8], flash: Range<u64>, family: u32) -> Result<Vec<u8>, String> {
    let mut pages = std::collections::BTreeMap::<u64, [u8; PAYLOAD_BYTES]>::new();
    for (address, bytes) in loadable(elf)? {
        let end = address + bytes.len() as u64;
        if address < flash.start || end > flash.end {
            return Err(format!("{} bytes at 0x{address:08x} are not in the flash (0x{:08x}..0x{:08x})", bytes.len(), flash.start, flash.end));
        }
        for (at, byte) in (address..end).zip(bytes) {
            let page = pages.entry(at - at % PAYLOAD_BYTES as u64).or_insert([0; PAYLOAD_BYTES]);
            page[(at % PAYLOAD_BYTES as u64) as usize] = byte;
        }
    }
    if pages.is_empty() {
        return Err("the ELF stores nothing in flash".into());
    }
    let total = pages.len() as u32;
    let mut file = Vec::with_capacity(pages.len() * BLOCK_BYTES);
    for (number, (address, payload)) in pages.into_iter().enumerate() {
        let address = u32::try_from(address).map_err(|_| format!("0x{address:x} is past 32 bits"))?;
        for word in [MAGIC_START0, MAGIC_START1, FLAG_FAMILY_ID, address, PAYLOAD_BYTES as u32, number as u32, total, family] {
            file.extend_from_slice(&word.to_le_bytes());
        }
        file.extend_from_slice(&payload);
        file.resize(file.len() + (BLOCK_BYTES - 32 - 4 - PAYLOAD_BYTES), 0);
        file.extend_from_slice(&MAGIC_END.to_le_bytes());
    }
    Ok(file)
}

/// What a UF2 file writes: each block's address and payload, after checking every block as the
/// RP2040's boot ROM would take it (magic numbers, the family, 256-byte payloads at 256-byte
/// boundaries, blocks numbered in order with the right total). The problems name the block.
pub fn blocks(uf2: &[u8], family: u32) -> Result<Vec<(u64, Vec<u8>)>, Vec<String>> {
    if uf2.is_empty() || !uf2.len().is_multiple_of(BLOCK_BYTES) {
        return Err(vec![format!("{} bytes: not a whole number of {BLOCK_BYTES}-byte blocks", uf2.len())]);
    }
    let count = uf2.len() / BLOCK_BYTES;
    let mut problems = Vec::new();
    let mut written = Vec::new();
    for (index, block) in uf2.chunks_exact(BLOCK_BYTES).enumerate() {
        let word = |at: usize| u32::from_le_bytes([block[at], block[at + 1], block[at + 2], block[at + 3]]);
        let mut problem = |text: String| problems.push(format!("block {index}: {text}"));
        if word(0) != MAGIC_START0 || word(4) != MAGIC_START1 || word(BLOCK_BYTES - 4) != MAGIC_END {
            problem("bad magic numbers".into());
            continue;
        }
        if word(8) & FLAG_FAMILY_ID == 0 || word(28) != family {
            problem(format!("family 0x{:08x} (flags 0x{:08x}), expected 0x{family:08x}", word(28), word(8)));
        }
        let (address, size, number, total) = (word(12), word(16) as usize, word(20) as usize, word(24) as usize);
        if number != index || total != count {
            problem(format!("numbered {number} of {total}, expected {index} of {count}"));
        }
        if size != PAYLOAD_BYTES || !(address as usize).is_multiple_of(PAYLOAD_BYTES) {
            problem(format!("{size} bytes at 0x{address:08x}, expected {PAYLOAD_BYTES} at a {PAYLOAD_BYTES}-byte boundary"));
            continue;
        }
        written.push((u64::from(address), block[32..32 + size].to_vec()));
    }
    if problems.is_empty() {
        Ok(written)
    } else {
        Err(problems)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A minimal ELF32 with two loadable segments: 300 bytes at 0x1000_0000 and 8 at 0x1000_0400
    /// (the second, like `.data`, loaded at a physical address other than its virtual one).
    fn elf() -> Vec<u8> {
        let mut elf = vec![0u8; 52 + 2 * 32];
        elf[..6].copy_from_slice(&[0x7f, b'E', b'L', b'F', 1, 1]);
        elf[28..32].copy_from_slice(&52u32.to_le_bytes());
        elf[42..44].copy_from_slice(&32u16.to_le_bytes());
        elf[44..46].copy_from_slice(&2u16.to_le_bytes());
        let data = elf.len() as u32;
        for (index, (physical, virtual_address, size)) in [(0x1000_0000u32, 0x1000_0000u32, 300u32), (0x1000_0400, 0x2000_0000, 8)].into_iter().enumerate() {
            let header = 52 + index * 32;
            let offset = data + if index == 0 { 0 } else { 300 };
            for (at, value) in [(0, PT_LOAD), (4, offset), (8, virtual_address), (12, physical), (16, size), (20, size)] {
                elf[header + at..header + at + 4].copy_from_slice(&value.to_le_bytes());
            }
        }
        elf.extend((0..308u32).map(|i| (i % 251) as u8 + 1));
        elf
    }

    #[test]
    fn every_loadable_byte_is_in_a_block_and_the_blocks_check() {
        let elf = elf();
        let uf2 = from_elf(&elf, 0x1000_0000..0x1020_0000, RP2040_FAMILY).unwrap();
        // Pages 0x1000_0000, 0x1000_0100 (bytes 256..300) and 0x1000_0400.
        assert_eq!(uf2.len(), 3 * BLOCK_BYTES);
        let written = blocks(&uf2, RP2040_FAMILY).unwrap();
        assert_eq!(written.iter().map(|(address, _)| *address).collect::<Vec<_>>(), [0x1000_0000, 0x1000_0100, 0x1000_0400]);
        for (address, bytes) in loadable(&elf).unwrap() {
            for (at, byte) in (address..).zip(bytes) {
                let (page, payload) = written.iter().find(|(page, _)| (*page..page + 256).contains(&at)).unwrap();
                assert_eq!(payload[(at - page) as usize], byte, "0x{at:x}");
            }
        }
        // The rest of a touched page is zero.
        assert!(written[1].1[300 - 256..].iter().all(|byte| *byte == 0));
    }

    #[test]
    fn a_block_the_boot_rom_would_refuse_is_named() {
        let uf2 = from_elf(&elf(), 0x1000_0000..0x1020_0000, RP2040_FAMILY).unwrap();
        let mut wrong_family = uf2.clone();
        wrong_family[BLOCK_BYTES + 28..BLOCK_BYTES + 32].copy_from_slice(&0x1234_5678u32.to_le_bytes());
        assert_eq!(blocks(&wrong_family, RP2040_FAMILY).unwrap_err(), ["block 1: family 0x12345678 (flags 0x00002000), expected 0xe48bff56"]);
        let mut misnumbered = uf2.clone();
        misnumbered[2 * BLOCK_BYTES + 20] = 7;
        assert_eq!(blocks(&misnumbered, RP2040_FAMILY).unwrap_err(), ["block 2: numbered 7 of 3, expected 2 of 3"]);
        let mut broken = uf2.clone();
        broken[0] ^= 1;
        assert_eq!(blocks(&broken, RP2040_FAMILY).unwrap_err(), ["block 0: bad magic numbers"]);
        assert!(blocks(&uf2[..700], RP2040_FAMILY).is_err());
        // Bytes outside the flash make no file.
        assert!(from_elf(&elf(), 0x1000_0000..0x1000_0200, RP2040_FAMILY).unwrap_err().contains("not in the flash"));
    }
}
