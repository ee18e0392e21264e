//! PGA compressed (FILEOUT=ON, PGA=ON, COMPRESS=ON; digest §7.2): the thesis's `linecompress`.
//!
//! There is no file header: the file is one record per row, in the order y = vy2 … vy1:
//!
//! ```text
//! 0xD9        PGA command "write encoded line of pixels"
//! y   (LE16)  line number
//! x1  (LE16)  = vx1
//! x2  (LE16)  = vx2
//! packets...  until x2 - x1 + 1 pixels are covered
//! ```
//!
//! Packets:
//! - `COUNT` in 0..=127, then one byte P: the next COUNT+1 pixels are all P (a *run*);
//! - `COUNT` in 128..=255, then COUNT−127 bytes: that many pixels given literally.
//!
//! [`compress_row`] reproduces `linecompress` exactly, quirks included, so that its output is
//! byte-identical to the thesis's files:
//! - a literal packet always takes at least two pixels, even when the second starts a run;
//! - a literal packet ends *before* a pixel equal to its successor, and *at* a pixel equal to its
//!   predecessor (that pixel was already taken as the literal's last byte, so the following run
//!   starts one pixel late);
//! - the literal loop compares with the byte one past the end of the row (`buf[p+1]` when one
//!   pixel is left); that byte counts as "different" (§11 B20: the C code read whatever was in
//!   memory there, which only mattered for that one comparison);
//! - a single pixel left at the end becomes a run of one (`0x00, P`).
//!
//! The encoder never writes the 1-pixel literal (`COUNT` = 128); the decoder accepts it.

/// The record id byte.
pub const ID: u8 = 0xD9;

/// The record header: id, y, x1, x2.
pub const RECORD_HEADER_LEN: usize = 7;

/// The longest run packet and the longest literal packet, in pixels.
pub const MAX_PACKET_PIXELS: usize = 128;

/// The worst-case length of one record (header included) for a row of `width` pixels:
/// `7 + width + ceil(width / 2)`.
///
/// Why: a run packet costs 2 bytes for at least 2 pixels, a literal packet n + 1 bytes for
/// n ≥ 2 pixels (1.5 bytes a pixel at worst), and the single trailing pixel 2 bytes. With k
/// literal packets over L pixels the packets cost at most L + k (+ 2 for a trailing pixel), k ≤ L / 2, which
/// is largest for rows like `0,1,1,2,2,3,3,…` (all two-pixel literals) and gives the bound; the
/// tests check by exhaustive search that it is reached for every small width. The thesis
/// allocated only 2·width bytes, which is too small (with its 7-byte header) for widths under 14.
pub const fn max_compressed_row_len(width: usize) -> usize {
    RECORD_HEADER_LEN.saturating_add(width).saturating_add(width / 2 + width % 2)
}

/// Compresses one row exactly as `linecompress(bufin, bufout, y, x1, x2)` did, writing the
/// 7-byte record header and the packets into `out`, and returns the record's length.
///
/// `row` holds pixels x1..=x2, so `row.len()` must be `x2 − x1 + 1`, and `out` must hold
/// [`max_compressed_row_len`]`(row.len())` bytes. If either does not hold (or x1 > x2), nothing
/// is written and the result is 0; a real record is never empty, so 0 always means misuse.
pub fn compress_row(row: &[u8], y: u16, x1: u16, x2: u16, out: &mut [u8]) -> usize {
    if x1 > x2 || usize::from(x2 - x1) + 1 != row.len() || out.len() < max_compressed_row_len(row.len()) {
        return 0;
    }
    let [yl, yh] = y.to_le_bytes();
    let [x1l, x1h] = x1.to_le_bytes();
    let [x2l, x2h] = x2.to_le_bytes();
    out[..RECORD_HEADER_LEN].copy_from_slice(&[ID, yl, yh, x1l, x1h, x2l, x2h]);
    let mut o = RECORD_HEADER_LEN;

    // A transcription of the thesis's loop. Invariant: p + len == row.len().
    let mut len = row.len();
    let mut p = 0;
    // `buf[p] != buf[p+1]`, with the byte one past the end of the row counting as different.
    let differs_from_next = |p: usize| row.get(p + 1).is_none_or(|next| *next != row[p]);
    while len > 1 {
        if row[p] == row[p + 1] {
            // Replicate run.
            let mut count: u8 = 1;
            len -= 2;
            p += 2;
            while len > 0 && count < 127 && row[p] == row[p - 1] {
                count += 1;
                len -= 1;
                p += 1;
            }
            out[o] = count; // covers count + 1 pixels (2..=128)
            out[o + 1] = row[p - 1];
            o += 2;
        } else {
            // Literal run.
            let t = p;
            let mut count: u8 = 1;
            len -= 2;
            p += 2;
            while len > 0 && count < 127 && row[p] != row[p - 1] && differs_from_next(p) {
                len -= 1;
                count += 1;
                p += 1;
            }
            out[o] = count + 128; // count + 1 literal bytes (2..=128) follow
            let literal = &row[t..p];
            out[o + 1..o + 1 + literal.len()].copy_from_slice(literal);
            o += 1 + literal.len();
        }
    }
    if len > 0 {
        // The single trailing pixel, as a run of one.
        out[o] = 0;
        out[o + 1] = row[p];
        o += 2;
    }
    o
}
