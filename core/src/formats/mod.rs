//! The thesis's image and look-up-table file formats, byte by byte (§4.2.2–4.2.3; digest §7).
//!
//! All multi-byte integers are 16-bit little-endian (the AT's native `int`; the digest fixes LE
//! for every machine). Rows are stored top row first, y = vy2 down to vy1, each left to right.
//!
//! | format | first byte | layout |
//! |---|---|---|
//! | [`pga_uncompressed`] | `0xFF` | 9-byte header (id, vx1, vx2, vy1, vy2), then one palette index per pixel |
//! | [`pga_compressed`] | `0xD9` | no header: one `0xD9` record per row (y, x1, x2, packets) |
//! | [`rgb`] | `0x00` | 9-byte header, then R, G, B per pixel |
//! | [`lut`] | — | 256 words `(r << 8) \| (g << 4) \| b`, for indices 0..=255 |
//!
//! Encoding needs no allocation: headers are returned as arrays, and
//! [`pga_compressed::compress_row`] writes into a caller's buffer of
//! [`pga_compressed::max_compressed_row_len`] bytes.
//!
//! Decoding ([`decode`], [`decode_indices_into`], [`decode_rgb_into`]) reads a whole file from a
//! byte slice. It first validates the file completely, then delivers it, so a caller never sees
//! part of a bad file. Every malformed input gives a [`FormatError`] naming the problem and its
//! byte offset; no input panics.

mod decode;
mod error;
pub mod lut;
pub mod pga_compressed;
pub mod pga_uncompressed;
pub mod rgb;

pub use decode::{decode, decode_indices_into, decode_rgb_into, identify, inspect, DecodedEvent, ImageFormat, ImageInfo};
pub use error::{Axis, FormatError, FormatErrorKind};

use crate::model::Viewport;

/// The length of the 9-byte header shared by the uncompressed PGA and the RGB formats.
pub const HEADER_LEN: usize = 9;

/// `id, vx1, vx2, vy1, vy2`, each coordinate 16-bit little-endian.
const fn header(id: u8, viewport: Viewport) -> [u8; HEADER_LEN] {
    let [x1l, x1h] = viewport.x1.to_le_bytes();
    let [x2l, x2h] = viewport.x2.to_le_bytes();
    let [y1l, y1h] = viewport.y1.to_le_bytes();
    let [y2l, y2h] = viewport.y2.to_le_bytes();
    [id, x1l, x1h, x2l, x2h, y1l, y1h, y2l, y2h]
}

/// The little-endian word at `offset`, if the slice holds it.
fn le16(bytes: &[u8], offset: usize) -> Option<u16> {
    match bytes.get(offset..offset.checked_add(2)?) {
        Some(&[low, high]) => Some(u16::from_le_bytes([low, high])),
        _ => None,
    }
}

#[cfg(test)]
mod tests;
