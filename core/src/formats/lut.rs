//! The look-up-table file (`savecolors`, `readcolors`; §4.2.2, digest §7.4).
//!
//! 256 little-endian words, one per LUT index 0..=255. Each word packs red in bits 11..8, green
//! in bits 7..4 and blue in bits 3..0; bits 15..12 are ignored on reading and written as 0.
//! The image files do not contain the LUT.

use super::{FormatError, FormatErrorKind};
use crate::model::{Palette, Rgb4};

/// The file's length: 256 words.
pub const LEN: usize = 512;

/// The LUT file for `palette`. Channels above 15 keep only their low 4 bits (the word packs 4).
pub fn encode_lut(palette: &Palette) -> [u8; LEN] {
    let mut bytes = [0u8; LEN];
    for (pair, entry) in bytes.chunks_exact_mut(2).zip(palette.entries.iter()) {
        let masked = Rgb4::new(entry.r & 0xF, entry.g & 0xF, entry.b & 0xF);
        pair.copy_from_slice(&masked.to_word().to_le_bytes());
    }
    bytes
}

/// Reads a LUT file. It must be exactly [`LEN`] bytes: a shorter file is truncated, a longer
/// one is not a LUT file.
pub fn decode_lut(bytes: &[u8]) -> Result<Palette, FormatError> {
    if bytes.len() != LEN {
        let offset = bytes.len().min(LEN);
        return Err(FormatError::new(FormatErrorKind::LutLength { len: bytes.len() }, offset));
    }
    let mut palette = Palette::grey();
    for (entry, pair) in palette.entries.iter_mut().zip(bytes.chunks_exact(2)) {
        if let [low, high] = *pair {
            *entry = Rgb4::from_word(u16::from_le_bytes([low, high]));
        }
    }
    Ok(palette)
}
