//! The RGB-mode file (PGA=OFF, FILEOUT=ON; digest §7.3).
//!
//! ```text
//! 0x00, vx1, vx2, vy1, vy2 (LE16 each)   9-byte header
//! then R, G, B per pixel, rows y = vy2 down to vy1, each row x = vx1..vx2
//! ```
//!
//! The thesis's `rgbtrace` allocated its row buffer as `3*vx2 - vx1 + 1` bytes, two bytes short
//! when vx1 = 0 (§11 B9); a row here is always 3·(vx2 − vx1 + 1) bytes.

use crate::model::Viewport;

/// The id byte.
pub const ID: u8 = 0x00;

/// The header length.
pub const HEADER_LEN: usize = super::HEADER_LEN;

/// Bytes per pixel: R, G, B.
pub const BYTES_PER_PIXEL: usize = 3;

/// The 9-byte header for `viewport`; the pixels follow it, top row first.
pub const fn write_header(viewport: Viewport) -> [u8; HEADER_LEN] {
    super::header(ID, viewport)
}

/// The whole file's length for `viewport` (header plus three bytes per pixel), or `None` if the
/// viewport is reversed.
pub const fn file_len(viewport: Viewport) -> Option<u64> {
    data_len(viewport, BYTES_PER_PIXEL as u64)
}

/// Header plus `bytes_per_pixel` per pixel of `viewport`, in `u64`.
pub(super) const fn data_len(viewport: Viewport, bytes_per_pixel: u64) -> Option<u64> {
    if viewport.x1 > viewport.x2 || viewport.y1 > viewport.y2 {
        return None;
    }
    let width = (viewport.x2 - viewport.x1) as u64 + 1;
    let height = (viewport.y2 - viewport.y1) as u64 + 1;
    Some(HEADER_LEN as u64 + width * height * bytes_per_pixel)
}
