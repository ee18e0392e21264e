//! Byte-level checks worked out by hand from the digest's §7, round trips, and decoder
//! robustness against arbitrary bytes.

extern crate std;

use std::vec;
use std::vec::Vec;

use super::pga_compressed::{compress_row, max_compressed_row_len};
use super::*;
use crate::model::Rgb888;
use crate::pixel::{FrameBuffer, PixelSink};
use crate::model::{Palette, Rgb4};

/// A tiny deterministic generator (xorshift32).
struct XorShift(u32);

impl XorShift {
    fn next(&mut self) -> u32 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.0 = x;
        x
    }
    fn below(&mut self, n: u32) -> u32 {
        self.next() % n
    }
    fn byte(&mut self) -> u8 {
        self.next() as u8
    }
}

/// Compresses `row` as pixels x1..x1+len-1 of line y and returns the packets only (the header
/// checked separately).
fn compress(row: &[u8], y: u16, x1: u16) -> Vec<u8> {
    let x2 = x1 + row.len() as u16 - 1;
    let mut out = vec![0u8; max_compressed_row_len(row.len())];
    let n = compress_row(row, y, x1, x2, &mut out);
    assert!(n >= pga_compressed::RECORD_HEADER_LEN + 2, "row {row:?}");
    let [yl, yh] = y.to_le_bytes();
    let [al, ah] = x1.to_le_bytes();
    let [bl, bh] = x2.to_le_bytes();
    assert_eq!(&out[..7], &[0xD9, yl, yh, al, ah, bl, bh]);
    out.truncate(n);
    out.split_off(7)
}

fn packets(row: &[u8]) -> Vec<u8> {
    compress(row, 0, 0)
}

/// Decodes one complete file of palette indices into a Vec (top row first) with its info.
fn decode_indices(bytes: &[u8]) -> Result<(ImageInfo, Vec<u8>), FormatError> {
    let info = inspect(bytes)?;
    let mut pixels = vec![0xEEu8; info.pixel_count() as usize];
    let mut sink = FrameBuffer::new(&mut pixels, info.width() as u16, info.height() as u16).unwrap();
    let again = decode_indices_into(bytes, &mut sink)?;
    assert_eq!(again, info);
    Ok((info, pixels))
}

fn compressed_file(viewport: Viewport, pixels: &[u8]) -> Vec<u8> {
    let width = (viewport.x2 - viewport.x1) as usize + 1;
    let mut file = Vec::new();
    let mut out = vec![0u8; max_compressed_row_len(width)];
    for (row, y) in pixels.chunks(width).zip((viewport.y1..=viewport.y2).rev()) {
        let n = compress_row(row, y, viewport.x1, viewport.x2, &mut out);
        assert!(n > 0);
        file.extend_from_slice(&out[..n]);
    }
    file
}

fn raw_file(header: [u8; 9], data: &[u8]) -> Vec<u8> {
    let mut file = header.to_vec();
    file.extend_from_slice(data);
    file
}

const VIEWPORT: Viewport = Viewport { x1: 0x0102, x2: 0x0105, y1: 0x0A00, y2: 0x0A02 };

// ---------------------------------------------------------------------------------------------
// linecompress, by hand.

#[test]
fn thesis_example_row_compresses_to_the_hand_worked_bytes() {
    // [5,5,5,1,2,3,3], len = 7, p = 0:
    //   buf[0] == buf[1]: run. count = 1, len = 5, p = 2; buf[2] == buf[1]: count = 2, len = 4,
    //     p = 3; buf[3] = 1 != 5: stop. Emit 2, buf[2] = 5 (three 5s).
    //   len = 4, p = 3: buf[3] = 1 != buf[4] = 2: literal. t = 3, count = 1, len = 2, p = 5;
    //     buf[5] = 3 != buf[4] = 2 but buf[5] == buf[6] = 3: stop. Emit 1 + 128 = 0x81, 1, 2.
    //   len = 2, p = 5: buf[5] == buf[6]: run. count = 1, len = 0, p = 7. Emit 1, 3.
    //   len = 0: no trailing pixel.
    let mut out = [0u8; 32];
    let n = compress_row(&[5, 5, 5, 1, 2, 3, 3], 10, 2, 8, &mut out);
    assert_eq!(&out[..n], &[0xD9, 10, 0, 2, 0, 8, 0, 0x02, 5, 0x81, 1, 2, 0x01, 3]);
}

#[test]
fn record_header_is_little_endian_y_x1_x2() {
    let mut out = [0u8; 16];
    let n = compress_row(&[9, 9], 0x1234, 0xABCD, 0xABCE, &mut out);
    assert_eq!(&out[..n], &[0xD9, 0x34, 0x12, 0xCD, 0xAB, 0xCE, 0xAB, 0x01, 9]);
}

#[test]
fn runs_of_128_and_129_equal_pixels() {
    // 128: run, count goes 1 -> 127 in 126 steps, consuming all 128 pixels: 0x7F, v.
    assert_eq!(packets(&[7; 128]), [0x7F, 7]);
    // 129: the run stops at count 127 (128 pixels) with len = 1 left, so the loop ends and
    // the last pixel is the trailing run of one: 0x00, v.
    assert_eq!(packets(&[7; 129]), [0x7F, 7, 0x00, 7]);
    // 130: the last two make a fresh run of two.
    assert_eq!(packets(&[7; 130]), [0x7F, 7, 0x01, 7]);
    // 256: two full runs.
    assert_eq!(packets(&[7; 256]), [0x7F, 7, 0x7F, 7]);
    assert_eq!(packets(&[7; 2]), [0x01, 7]);
}

#[test]
fn literal_runs_of_128_and_more() {
    let distinct: Vec<u8> = (0..=255).collect();
    // 128 distinct: literal, t = 0, count 1 -> 127 in 126 steps (p = 128, len = 0): 0xFF and
    // 128 bytes.
    let mut expected = vec![0xFF];
    expected.extend(0..128);
    assert_eq!(packets(&distinct[..128]), expected);
    // 129 distinct: the literal stops at count 127 with len = 1: trailing 0x00, 128.
    let mut expected = vec![0xFF];
    expected.extend(0..128);
    expected.extend([0x00, 128]);
    assert_eq!(packets(&distinct[..129]), expected);
    // 130 distinct: the last two become a two-pixel literal: 0x81, 128, 129.
    let mut expected = vec![0xFF];
    expected.extend(0..128);
    expected.extend([0x81, 128, 129]);
    assert_eq!(packets(&distinct[..130]), expected);
    // 256 distinct: exactly two full literals.
    let mut expected = vec![0xFF];
    expected.extend(0..128);
    expected.push(0xFF);
    expected.extend(128..=255);
    assert_eq!(packets(&distinct), expected);
}

#[test]
fn single_trailing_pixel_is_a_run_of_one() {
    // Width 1: the loop never runs; 0x00, v.
    assert_eq!(packets(&[42]), [0x00, 42]);
    // [4,4,9]: run of two (count 1, len 1, p = 2; buf[2] = 9 != 4 stops it), then 9 alone.
    assert_eq!(packets(&[4, 4, 9]), [0x01, 4, 0x00, 9]);
    // [1,2,3,3,8]: literal 1,2 (buf[2] == buf[3] stops it), run 3,3, then 8 alone.
    assert_eq!(packets(&[1, 2, 3, 3, 8]), [0x81, 1, 2, 0x01, 3, 0x00, 8]);
}

#[test]
fn the_byte_past_the_end_counts_as_different() {
    // [1,2,3]: literal t = 0, count 1, len = 1, p = 2. The loop compares buf[2] with buf[3],
    // one past the row; "different", so the literal takes the 3 as well: 0x82, 1, 2, 3.
    // (Treating it as equal would give 0x81, 1, 2, 0x00, 3.)
    assert_eq!(packets(&[1, 2, 3]), [0x82, 1, 2, 3]);
    // Same when the last pixel equals the byte that follows the row in the caller's memory.
    let memory = [1u8, 2, 3, 3];
    let mut out = [0u8; 16];
    let n = compress_row(&memory[..3], 0, 0, 2, &mut out);
    assert_eq!(&out[7..n], &[0x82, 1, 2, 3]);
}

#[test]
fn a_literal_takes_at_least_two_pixels_even_when_the_second_starts_a_run() {
    // [1,2,2,2]: buf[0] != buf[1]: literal, t = 0, p = 2 at once; buf[2] == buf[1] stops it:
    // 0x81, 1, 2. Then p = 2, len = 2: run of the last two 2s: 0x01, 2.
    assert_eq!(packets(&[1, 2, 2, 2]), [0x81, 1, 2, 0x01, 2]);
    // [1,2,2,2,2]: after the literal, the run takes three: 0x02, 2.
    assert_eq!(packets(&[1, 2, 2, 2, 2]), [0x81, 1, 2, 0x02, 2]);
    // [1,2,2]: literal 1,2 then the last 2 alone.
    assert_eq!(packets(&[1, 2, 2]), [0x81, 1, 2, 0x00, 2]);
}

#[test]
fn a_literal_stops_before_a_pixel_equal_to_its_successor() {
    // [1,2,3,4,4]: literal t = 0, p = 2: 3 differs from 2 and 4: count 2, p = 3; 4 == buf[4]:
    // stop. 0x82, 1, 2, 3; then run 0x01, 4.
    assert_eq!(packets(&[1, 2, 3, 4, 4]), [0x82, 1, 2, 3, 0x01, 4]);
    // Alternating pairs: every literal is two pixels (the worst case, 1.5 bytes a pixel).
    // [0,1,1,2,2,3]: literal 0,1 (buf[2] == buf[1]); p = 2: 1 != 2: literal 1,2 (buf[4] ==
    // buf[3]); p = 4: 2 != 3: literal t = 4, p = 6, len = 0: 2,3.
    assert_eq!(packets(&[0, 1, 1, 2, 2, 3]), [0x81, 0, 1, 0x81, 1, 2, 0x81, 2, 3]);
}

#[test]
fn misuse_writes_nothing_and_returns_zero() {
    let mut out = [0xAAu8; 64];
    assert_eq!(compress_row(&[1, 2, 3], 0, 5, 4, &mut out), 0, "x1 > x2");
    assert_eq!(compress_row(&[1, 2, 3], 0, 0, 3, &mut out), 0, "row length is not x2 - x1 + 1");
    assert_eq!(compress_row(&[], 0, 0, 0, &mut out), 0, "empty row");
    assert_eq!(compress_row(&[1, 2, 3], 0, 0, 2, &mut out[..max_compressed_row_len(3) - 1]), 0, "short buffer");
    assert!(out.iter().all(|&b| b == 0xAA));
}

#[test]
fn worst_case_bound_holds_and_is_reached() {
    assert_eq!(max_compressed_row_len(0), 7);
    assert_eq!(max_compressed_row_len(1), 9);
    assert_eq!(max_compressed_row_len(2), 10);
    assert_eq!(max_compressed_row_len(3), 12);
    assert_eq!(max_compressed_row_len(640), 7 + 960);
    assert_eq!(max_compressed_row_len(usize::MAX), usize::MAX);
    // Exhaustively over three colours for widths 1..=9: never above the bound, and reached.
    for width in 1..=9usize {
        let mut worst = 0;
        let mut row = vec![0u8; width];
        let mut out = vec![0u8; max_compressed_row_len(width)];
        for mut code in 0..3u32.pow(width as u32) {
            for pixel in row.iter_mut() {
                *pixel = (code % 3) as u8;
                code /= 3;
            }
            let n = compress_row(&row, 0, 0, width as u16 - 1, &mut out);
            assert!(n > 0 && n <= max_compressed_row_len(width));
            worst = worst.max(n);
        }
        assert_eq!(worst, max_compressed_row_len(width), "width {width}");
    }
    // And for a long row of alternating pairs.
    let row: Vec<u8> = (0..1001u32).map(|i| i.div_ceil(2) as u8).collect();
    let mut out = vec![0u8; max_compressed_row_len(row.len())];
    assert_eq!(compress_row(&row, 0, 0, 1000, &mut out), max_compressed_row_len(1001));
}

// ---------------------------------------------------------------------------------------------
// Headers and the LUT.

#[test]
fn header_bytes_of_each_format() {
    // vx1 = 0x0102, vx2 = 0x0105, vy1 = 0x0A00, vy2 = 0x0A02, each low byte first.
    assert_eq!(pga_uncompressed::write_header(VIEWPORT), [0xFF, 0x02, 0x01, 0x05, 0x01, 0x00, 0x0A, 0x02, 0x0A]);
    assert_eq!(rgb::write_header(VIEWPORT), [0x00, 0x02, 0x01, 0x05, 0x01, 0x00, 0x0A, 0x02, 0x0A]);
    // The thesis's default 640x480 viewport: 0..639 = 0x027F, 0..479 = 0x01DF.
    let full = Viewport { x1: 0, x2: 639, y1: 0, y2: 479 };
    assert_eq!(pga_uncompressed::write_header(full), [0xFF, 0, 0, 0x7F, 0x02, 0, 0, 0xDF, 0x01]);
    assert_eq!(pga_uncompressed::file_len(full), Some(9 + 640 * 480));
    assert_eq!(rgb::file_len(full), Some(9 + 3 * 640 * 480));
    let huge = Viewport { x1: 0, x2: u16::MAX, y1: 0, y2: u16::MAX };
    assert_eq!(rgb::file_len(huge), Some(9 + 3 * 65536 * 65536));
    assert_eq!(rgb::file_len(Viewport { x1: 2, x2: 1, y1: 0, y2: 0 }), None);
}

#[test]
fn lut_words_are_r_g_b_nibbles_little_endian() {
    let mut palette = Palette::grey();
    palette.entries[0] = Rgb4::new(0xA, 0x4, 0xF);
    palette.entries[255] = Rgb4::new(1, 2, 3);
    let bytes = lut::encode_lut(&palette);
    assert_eq!(bytes.len(), 512);
    assert_eq!(&bytes[..2], &[0x4F, 0x0A]); // 0x0A4F
    assert_eq!(&bytes[2..4], &[0x11, 0x01]); // grey shade 1: 0x0111
    assert_eq!(&bytes[30..32], &[0xFF, 0x0F]); // grey shade 15: 0x0FFF
    assert_eq!(&bytes[510..], &[0x23, 0x01]);
    assert_eq!(lut::decode_lut(&bytes), Ok(palette));
    // Bits 15..12 are don't-care on reading.
    let mut dirty = bytes;
    dirty[1] |= 0xF0;
    assert_eq!(lut::decode_lut(&dirty), Ok(palette));
    // Out-of-range channels keep their low nibble instead of spilling into the next field.
    let mut wide = Palette::grey();
    wide.entries[3] = Rgb4::new(0x1F, 0, 0);
    assert_eq!(&lut::encode_lut(&wide)[6..8], &[0x00, 0x0F]);
}

#[test]
fn lut_of_the_wrong_length_is_an_error() {
    let bytes = lut::encode_lut(&Palette::grey());
    let short = lut::decode_lut(&bytes[..511]).unwrap_err();
    assert_eq!(short, FormatError::new(FormatErrorKind::LutLength { len: 511 }, 511));
    let mut long = bytes.to_vec();
    long.push(0);
    assert_eq!(lut::decode_lut(&long).unwrap_err().offset, 512);
    assert!(lut::decode_lut(&[]).is_err());
    let mut rng = XorShift(99);
    for _ in 0..200 {
        let random: Vec<u8> = (0..512).map(|_| rng.byte()).collect();
        let palette = lut::decode_lut(&random).unwrap();
        assert!(palette.entries.iter().all(|e| e.r < 16 && e.g < 16 && e.b < 16));
        // Re-encoding drops only the don't-care nibble.
        let again = lut::encode_lut(&palette);
        for (a, b) in again.chunks(2).zip(random.chunks(2)) {
            assert_eq!((a[0], a[1]), (b[0], b[1] & 0x0F));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Decoding.

#[test]
fn uncompressed_file_decodes_top_row_first() {
    // 4 x 3 pixels; file rows are y = 0x0A02 (top), 0x0A01, 0x0A00.
    let data: Vec<u8> = (0..12).collect();
    let file = raw_file(pga_uncompressed::write_header(VIEWPORT), &data);
    let mut events = Vec::new();
    let info = decode(&file, &mut |event| events.push(event)).unwrap();
    assert_eq!(info, ImageInfo { format: ImageFormat::PgaUncompressed, viewport: VIEWPORT, rows: 3, complete: true });
    assert_eq!(
        events,
        [
            DecodedEvent::Indices { x: 0, row: 0, pixels: &data[0..4] },
            DecodedEvent::RowDone { row: 0 },
            DecodedEvent::Indices { x: 0, row: 1, pixels: &data[4..8] },
            DecodedEvent::RowDone { row: 1 },
            DecodedEvent::Indices { x: 0, row: 2, pixels: &data[8..12] },
            DecodedEvent::RowDone { row: 2 },
        ]
    );
    assert_eq!(decode_indices(&file).unwrap().1, data);
}

#[test]
fn compressed_file_decodes_record_by_record() {
    // Two records, y = 7 then 6, x = 3..9: [5,5,5,1,2,3,3] and [9; 7].
    let mut file = Vec::new();
    file.extend([0xD9, 7, 0, 3, 0, 9, 0, 0x02, 5, 0x81, 1, 2, 0x01, 3]);
    file.extend([0xD9, 6, 0, 3, 0, 9, 0, 0x06, 9]);
    let mut events = Vec::new();
    let info = decode(&file, &mut |event| events.push(event)).unwrap();
    let viewport = Viewport { x1: 3, x2: 9, y1: 6, y2: 7 };
    assert_eq!(info, ImageInfo { format: ImageFormat::PgaCompressed, viewport, rows: 2, complete: true });
    assert_eq!(
        events,
        [
            DecodedEvent::Fill { x: 0, row: 0, count: 3, index: 5 },
            DecodedEvent::Indices { x: 3, row: 0, pixels: &[1, 2] },
            DecodedEvent::Fill { x: 5, row: 0, count: 2, index: 3 },
            DecodedEvent::RowDone { row: 0 },
            DecodedEvent::Fill { x: 0, row: 1, count: 7, index: 9 },
            DecodedEvent::RowDone { row: 1 },
        ]
    );
    assert_eq!(decode_indices(&file).unwrap().1, [5, 5, 5, 1, 2, 3, 3, 9, 9, 9, 9, 9, 9, 9]);
}

#[test]
fn compressed_viewport_is_the_bounding_box_and_gaps_are_left_alone() {
    // y = 20, x 5..6; y = 18 (19 missing), x 4..5. A one-pixel literal (0x80) is legal.
    let file = [0xD9, 20, 0, 5, 0, 6, 0, 0x01, 1, 0xD9, 18, 0, 4, 0, 5, 0, 0x80, 2, 0x00, 3];
    let (info, pixels) = decode_indices(&file).unwrap();
    assert_eq!(info.viewport, Viewport { x1: 4, x2: 6, y1: 18, y2: 20 });
    assert_eq!((info.rows, info.complete), (2, false));
    const E: u8 = 0xEE; // untouched
    assert_eq!(pixels, [E, 1, 1, E, E, E, 2, 3, E]);
    // Same x range but a missing row is also incomplete.
    let gap = [0xD9, 5, 0, 0, 0, 0, 0, 0x00, 1, 0xD9, 3, 0, 0, 0, 0, 0, 0x00, 1];
    assert!(!inspect(&gap).unwrap().complete);
}

#[test]
fn rgb_file_decodes_to_rgb_and_pga_through_the_palette() {
    let viewport = Viewport { x1: 0, x2: 1, y1: 0, y2: 1 };
    let data = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12];
    let file = raw_file(rgb::write_header(viewport), &data);
    let mut pixels = [[0u8; 3]; 4];
    let mut sink = FrameBuffer::new(&mut pixels, 2, 2).unwrap();
    let info = decode_rgb_into(&file, &Palette::grey(), &mut sink).unwrap();
    assert_eq!(info.format, ImageFormat::Rgb);
    assert_eq!(pixels, [[1, 2, 3], [4, 5, 6], [7, 8, 9], [10, 11, 12]]);
    // An RGB file has no indices.
    let mut indices = [0u8; 4];
    let mut sink = FrameBuffer::new(&mut indices, 2, 2).unwrap();
    assert_eq!(decode_indices_into(&file, &mut sink), Err(FormatError::new(FormatErrorKind::NotIndexed, 0)));

    // A PGA file through a palette: index 16·g + s. Wide enough to cross the 32-pixel chunks.
    let mut palette = Palette::grey();
    palette.set_group_up(2, Rgb4::new(15, 0, 0));
    let viewport = Viewport { x1: 0, x2: 69, y1: 0, y2: 0 };
    let row: Vec<u8> = (0..70u32).map(|i| if i < 40 { 32 + (i % 16) as u8 } else { 7 }).collect();
    for file in [raw_file(pga_uncompressed::write_header(viewport), &row), compressed_file(viewport, &row)] {
        let mut pixels = vec![[0u8; 3]; 70];
        let mut sink = FrameBuffer::new(&mut pixels, 70, 1).unwrap();
        decode_rgb_into(&file, &palette, &mut sink).unwrap();
        let expected: Vec<Rgb888> = row.iter().map(|&i| palette.entry(i).to_rgb888()).collect();
        assert_eq!(pixels, expected);
        assert_eq!(pixels[15], [17 * 15, 0, 0]);
        assert_eq!(pixels[69], [7 * 17; 3]);
    }
}

#[test]
fn sinks_get_one_row_done_per_row() {
    struct Rows(Vec<u16>);
    impl PixelSink<u8> for Rows {
        fn set_pixel(&mut self, _x: u16, _y: u16, _value: u8) {}
        fn row_done(&mut self, y: u16) {
            self.0.push(y);
        }
    }
    let viewport = Viewport { x1: 10, x2: 12, y1: 100, y2: 103 };
    let file = compressed_file(viewport, &[1; 12]);
    let mut rows = Rows(Vec::new());
    decode_indices_into(&file, &mut rows).unwrap();
    assert_eq!(rows.0, [0, 1, 2, 3]);
}

// ---------------------------------------------------------------------------------------------
// Errors: what and where.

fn error(bytes: &[u8]) -> FormatError {
    let mut visited = false;
    let error = decode(bytes, &mut |_| visited = true).unwrap_err();
    assert!(!visited, "an invalid file delivers nothing");
    assert_eq!(inspect(bytes), Err(error));
    error
}

#[test]
fn errors_name_the_problem_and_the_offset() {
    use FormatErrorKind::*;
    assert_eq!(error(&[]), FormatError::new(Empty, 0));
    assert_eq!(error(&[0x42, 1, 2]), FormatError::new(UnknownId { id: 0x42 }, 0));
    assert_eq!(error(&[0xFF, 0, 0, 1]), FormatError::new(TruncatedHeader { needed: 9, available: 4 }, 4));
    assert_eq!(error(&[0x00, 5, 0, 4, 0, 0, 0, 0, 0]), FormatError::new(ReversedRange { axis: Axis::X, low: 5, high: 4 }, 1));
    assert_eq!(error(&[0xFF, 0, 0, 0, 0, 2, 0, 1, 0]), FormatError::new(ReversedRange { axis: Axis::Y, low: 2, high: 1 }, 5));
    // 2 x 2 uncompressed: 13 bytes.
    let header = pga_uncompressed::write_header(Viewport { x1: 0, x2: 1, y1: 0, y2: 1 });
    assert_eq!(error(&raw_file(header, &[1, 2, 3])), FormatError::new(TruncatedPixels { expected: 13, available: 12 }, 12));
    assert_eq!(error(&raw_file(header, &[1, 2, 3, 4, 5])), FormatError::new(TrailingBytes { expected: 13, available: 14 }, 13));
    // 2 x 2 RGB: 21 bytes.
    let header = rgb::write_header(Viewport { x1: 0, x2: 1, y1: 0, y2: 1 });
    assert_eq!(error(&raw_file(header, &[0; 11])), FormatError::new(TruncatedPixels { expected: 21, available: 20 }, 20));

    let record = [0xD9, 7, 0, 3, 0, 5, 0, 0x02, 4]; // y 7, x 3..5, run of 3
    assert_eq!(error(&record[..5]), FormatError::new(TruncatedHeader { needed: 7, available: 5 }, 5));
    assert_eq!(error(&record[..7]), FormatError::new(TruncatedPacket { y: 7, decoded: 0, width: 3 }, 7));
    assert_eq!(error(&record[..8]), FormatError::new(TruncatedPacket { y: 7, decoded: 0, width: 3 }, 8));
    assert_eq!(error(&[0xD9, 7, 0, 6, 0, 5, 0, 0x00, 1]), FormatError::new(ReversedRange { axis: Axis::X, low: 6, high: 5 }, 3));
    // A run of 4 in a 3-pixel row; then a literal of 3 after one pixel.
    assert_eq!(error(&[0xD9, 7, 0, 3, 0, 5, 0, 0x03, 4]), FormatError::new(PacketPastRow { y: 7, pixels: 4, remaining: 3 }, 7));
    assert_eq!(
        error(&[0xD9, 7, 0, 3, 0, 5, 0, 0x00, 4, 0x82, 1, 2, 3]),
        FormatError::new(PacketPastRow { y: 7, pixels: 3, remaining: 2 }, 9)
    );
    // A literal cut short by the end of the file.
    assert_eq!(error(&[0xD9, 7, 0, 3, 0, 5, 0, 0x00, 4, 0x81, 1]), FormatError::new(TruncatedPacket { y: 7, decoded: 1, width: 3 }, 11));
    // Garbage after a record; rows out of order.
    let mut file = record.to_vec();
    file.push(0x00);
    assert_eq!(error(&file), FormatError::new(NotARecord { found: 0 }, 9));
    let mut file = record.to_vec();
    file.extend(record);
    assert_eq!(error(&file), FormatError::new(RowOrder { y: 7, previous: 7 }, 10));
    let mut file = record.to_vec();
    file.extend([0xD9, 8, 0, 3, 0, 5, 0, 0x02, 4]);
    assert_eq!(error(&file), FormatError::new(RowOrder { y: 8, previous: 7 }, 10));
}

#[test]
fn errors_display_what_and_where() {
    use std::string::ToString;
    let text = error(&[0xD9, 7, 0, 3, 0, 5, 0, 0x03, 4]).to_string();
    assert_eq!(text, "packet of 4 pixels runs past the end of row y = 7 (3 pixels left) at byte offset 7");
    assert_eq!(error(&[0x42]).to_string(), "unknown format id byte 0x42 (expected 0xD9 compressed PGA, 0xFF uncompressed PGA or 0x00 RGB) at byte offset 0");
    let header = pga_uncompressed::write_header(Viewport { x1: 0, x2: 1, y1: 0, y2: 1 });
    assert_eq!(
        error(&raw_file(header, &[1, 2, 3, 4, 5, 6])).to_string(),
        "2 unexpected bytes after the pixel data (the header's viewport needs 13 bytes) at byte offset 13"
    );
    // Every kind displays something.
    for kind in [
        FormatErrorKind::Empty,
        FormatErrorKind::TruncatedHeader { needed: 9, available: 0 },
        FormatErrorKind::TrailingBytes { expected: 10, available: 1 },
        FormatErrorKind::LutLength { len: 3 },
        FormatErrorKind::NotIndexed,
        FormatErrorKind::RowOrder { y: 1, previous: 0 },
        FormatErrorKind::NotARecord { found: 1 },
        FormatErrorKind::TruncatedPixels { expected: 1, available: 0 },
    ] {
        assert!(FormatError::new(kind, 3).to_string().ends_with(" at byte offset 3"));
    }
}

// ---------------------------------------------------------------------------------------------
// Round trips and robustness.

/// A row mixing runs of random lengths with noise, over a small or a full alphabet.
fn random_row(rng: &mut XorShift, width: usize) -> Vec<u8> {
    let alphabet = [2, 3, 16, 256][rng.below(4) as usize];
    let mut row = Vec::with_capacity(width);
    while row.len() < width {
        let value = rng.below(alphabet) as u8;
        let length = match rng.below(4) {
            0 => 1 + rng.below(300) as usize,
            _ => 1 + rng.below(3) as usize,
        };
        for _ in 0..length.min(width - row.len()) {
            row.push(value);
        }
    }
    row
}

#[test]
fn compressed_rows_round_trip() {
    let mut rng = XorShift(0x1989_0001);
    for _ in 0..3000 {
        let width = 1 + rng.below(400) as usize;
        let row = random_row(&mut rng, width);
        let x1 = rng.below(65536 - width as u32) as u16;
        let y = rng.next() as u16;
        let mut out = vec![0u8; max_compressed_row_len(width)];
        let n = compress_row(&row, y, x1, x1 + width as u16 - 1, &mut out);
        assert!(n > 0 && n <= out.len());
        let (info, pixels) = decode_indices(&out[..n]).unwrap();
        assert_eq!(info.viewport, Viewport { x1, x2: x1 + width as u16 - 1, y1: y, y2: y });
        assert!(info.complete);
        assert_eq!(pixels, row);
    }
}

#[test]
fn whole_images_round_trip_in_every_format() {
    let mut rng = XorShift(0xC0FFEE);
    for _ in 0..200 {
        let width = 1 + rng.below(90) as u16;
        let height = 1 + rng.below(40) as u16;
        let x1 = rng.below(1000) as u16;
        let y1 = rng.below(1000) as u16;
        let viewport = Viewport { x1, x2: x1 + width - 1, y1, y2: y1 + height - 1 };
        let mut pixels = Vec::new();
        for _ in 0..height {
            pixels.extend(random_row(&mut rng, width as usize));
        }
        let expected_info = |format| ImageInfo { format, viewport, rows: height as u32, complete: true };

        let compressed = compressed_file(viewport, &pixels);
        assert_eq!(decode_indices(&compressed).unwrap(), (expected_info(ImageFormat::PgaCompressed), pixels.clone()));

        let uncompressed = raw_file(pga_uncompressed::write_header(viewport), &pixels);
        assert_eq!(uncompressed.len() as u64, pga_uncompressed::file_len(viewport).unwrap());
        assert_eq!(decode_indices(&uncompressed).unwrap(), (expected_info(ImageFormat::PgaUncompressed), pixels.clone()));

        let colours: Vec<Rgb888> = pixels.iter().map(|_| [rng.byte(), rng.byte(), rng.byte()]).collect();
        let rgb_file = raw_file(rgb::write_header(viewport), colours.as_flattened());
        assert_eq!(rgb_file.len() as u64, rgb::file_len(viewport).unwrap());
        let mut decoded = vec![[0u8; 3]; colours.len()];
        let mut sink = FrameBuffer::new(&mut decoded, width, height).unwrap();
        assert_eq!(decode_rgb_into(&rgb_file, &Palette::grey(), &mut sink).unwrap(), expected_info(ImageFormat::Rgb));
        assert_eq!(decoded, colours);
    }
}

/// Decodes `bytes` every way; an error is fine, a panic is not. Returns whether it decoded.
fn decodes(bytes: &[u8]) -> bool {
    let mut delivered = 0u64;
    let result = decode(bytes, &mut |event| {
        delivered += match event {
            DecodedEvent::Indices { pixels, .. } => pixels.len() as u64,
            DecodedEvent::Fill { count, .. } => count as u64,
            DecodedEvent::Rgb { bytes, .. } => bytes.len() as u64 / 3,
            DecodedEvent::RowDone { .. } => 0,
        }
    });
    if let Ok(info) = result {
        assert!(delivered <= info.pixel_count());
        if info.complete {
            assert_eq!(delivered, info.pixel_count());
        }
        // Through bounded sinks too (these small images fit a 64 x 64 mock).
        if info.width() <= 64 && info.height() <= 64 {
            let mut indices = crate::pixel::MockSink::<u8, 64, 64>::new(0);
            let _ = decode_indices_into(bytes, &mut indices);
            assert_eq!(indices.out_of_bounds, 0);
            let mut colours = crate::pixel::MockSink::<Rgb888, 64, 64>::new([0; 3]);
            decode_rgb_into(bytes, &Palette::grey(), &mut colours).unwrap();
            assert_eq!(colours.out_of_bounds, 0);
        }
    } else if let Err(error) = result {
        assert!(!std::format!("{error}").is_empty());
    }
    result.is_ok()
}

#[test]
fn random_bytes_never_panic() {
    let mut rng = XorShift(12345);
    for i in 0..20000 {
        let len = rng.below(if i % 2 == 0 { 24 } else { 300 }) as usize;
        let mut bytes: Vec<u8> = (0..len).map(|_| rng.byte()).collect();
        if let Some(first) = bytes.first_mut() {
            *first = [0xD9, 0xFF, 0x00, *first][i % 4];
        }
        decodes(&bytes);
    }
}

#[test]
fn truncated_and_mutated_files_never_panic() {
    let mut rng = XorShift(777);
    for _ in 0..60 {
        let width = 1 + rng.below(20) as u16;
        let height = 1 + rng.below(8) as u16;
        let viewport = Viewport { x1: 3, x2: 2 + width, y1: 5, y2: 4 + height };
        let mut pixels = Vec::new();
        for _ in 0..height {
            pixels.extend(random_row(&mut rng, width as usize));
        }
        let rgb_data: Vec<u8> = (0..pixels.len() * 3).map(|_| rng.byte()).collect();
        let files = [
            compressed_file(viewport, &pixels),
            raw_file(pga_uncompressed::write_header(viewport), &pixels),
            raw_file(rgb::write_header(viewport), &rgb_data),
        ];
        for (kind, file) in files.iter().enumerate() {
            assert!(decodes(file));
            for cut in 0..file.len() {
                let valid = decodes(&file[..cut]);
                // A header format is only valid whole; a D9 prefix is valid exactly when it ends
                // at a record boundary.
                if kind > 0 || cut == 0 {
                    assert!(!valid, "prefix of {cut} bytes");
                }
            }
            for _ in 0..100 {
                let mut mutated = file.clone();
                for _ in 0..1 + rng.below(3) {
                    let at = rng.below(mutated.len() as u32) as usize;
                    mutated[at] = rng.byte();
                }
                if kind > 0 && decodes(&mutated) {
                    // A header format stays valid only with a viewport of the same pixel count.
                    assert_eq!(inspect(&mutated).unwrap().pixel_count(), pixels.len() as u64);
                }
                mutated.push(rng.byte());
                decodes(&mutated);
            }
        }
    }
}

#[test]
fn identify_by_first_byte() {
    assert_eq!(identify(&[0xD9]), Ok(ImageFormat::PgaCompressed));
    assert_eq!(identify(&[0xFF]), Ok(ImageFormat::PgaUncompressed));
    assert_eq!(identify(&[0x00]), Ok(ImageFormat::Rgb));
    assert_eq!(identify(&[0x01]).unwrap_err().kind, FormatErrorKind::UnknownId { id: 1 });
    for format in [ImageFormat::PgaCompressed, ImageFormat::PgaUncompressed, ImageFormat::Rgb] {
        assert_eq!(ImageFormat::from_id(format.id()), Some(format));
    }
}

#[test]
fn a_full_width_row_of_65536_pixels() {
    let row: Vec<u8> = (0..65536u32).map(|i| if i % 1000 < 500 { 3 } else { (i % 7) as u8 }).collect();
    let mut out = vec![0u8; max_compressed_row_len(row.len())];
    let n = compress_row(&row, 9, 0, u16::MAX, &mut out);
    assert!(n > 0);
    let mut decoded = Vec::new();
    let info = decode(&out[..n], &mut |event| match event {
        DecodedEvent::Indices { x, pixels, .. } => {
            assert_eq!(x as usize, decoded.len());
            decoded.extend_from_slice(pixels);
        }
        DecodedEvent::Fill { x, count, index, .. } => {
            assert_eq!(x as usize, decoded.len());
            decoded.extend(core::iter::repeat_n(index, count as usize));
        }
        _ => {}
    })
    .unwrap();
    assert_eq!((info.width(), info.height(), info.pixel_count()), (65536, 1, 65536));
    assert_eq!(decoded, row);
    // And as an uncompressed file: the header says 0..65535.
    let file = raw_file(pga_uncompressed::write_header(info.viewport), &row);
    assert_eq!(inspect(&file).unwrap().width(), 65536);
}
