//! PGA uncompressed (FILEOUT=ON, PGA=ON, COMPRESS=OFF; digest §7.1).
//!
//! ```text
//! offset 0     : 0xFF                      id byte
//! offset 1..2  : vx1 (LE16)
//! offset 3..4  : vx2 (LE16)
//! offset 5..6  : vy1 (LE16)
//! offset 7..8  : vy2 (LE16)
//! offset 9..   : (vx2-vx1+1)*(vy2-vy1+1) palette indices, rows y = vy2 down to vy1,
//!                each row x = vx1..vx2
//! ```

use crate::model::Viewport;

/// The id byte.
pub const ID: u8 = 0xFF;

/// The header length.
pub const HEADER_LEN: usize = super::HEADER_LEN;

/// The 9-byte header for `viewport`; the raw rows follow it, top row first.
pub const fn write_header(viewport: Viewport) -> [u8; HEADER_LEN] {
    super::header(ID, viewport)
}

/// The whole file's length for `viewport` (header plus one byte per pixel), or `None` if the
/// viewport is reversed. Computed in `u64`: a full 65536 x 65536 viewport does not fit 32 bits.
pub const fn file_len(viewport: Viewport) -> Option<u64> {
    super::rgb::data_len(viewport, 1)
}
