//! Reading the three image formats back (the thesis's `loadpgafile`, digest §7.5, with a proper
//! record decoder in place of its broken compressed path, §11 B12; and the RGB format, which
//! `loadpgafile` ignored).

use super::{le16, pga_compressed, pga_uncompressed, rgb, Axis, FormatError, FormatErrorKind, HEADER_LEN};
use crate::model::Rgb888;
use crate::pixel::PixelSink;
use crate::model::Viewport;
use crate::model::Palette;

/// The three image formats, told apart by their first byte.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ImageFormat {
    /// 0xD9 row records ([`pga_compressed`]).
    PgaCompressed,
    /// 0xFF header and raw palette indices ([`pga_uncompressed`]).
    PgaUncompressed,
    /// 0x00 header and R, G, B per pixel ([`rgb`]).
    Rgb,
}

impl ImageFormat {
    /// The format's first byte.
    pub const fn id(self) -> u8 {
        match self {
            Self::PgaCompressed => pga_compressed::ID,
            Self::PgaUncompressed => pga_uncompressed::ID,
            Self::Rgb => rgb::ID,
        }
    }

    /// The format whose first byte is `id`.
    pub const fn from_id(id: u8) -> Option<Self> {
        match id {
            pga_compressed::ID => Some(Self::PgaCompressed),
            pga_uncompressed::ID => Some(Self::PgaUncompressed),
            rgb::ID => Some(Self::Rgb),
            _ => None,
        }
    }

    /// Whether the pixels are palette indices (both PGA formats) rather than RGB.
    pub const fn is_indexed(self) -> bool {
        !matches!(self, Self::Rgb)
    }

    pub const fn name(self) -> &'static str {
        match self {
            Self::PgaCompressed => "PGA compressed (0xD9)",
            Self::PgaUncompressed => "PGA uncompressed (0xFF)",
            Self::Rgb => "RGB (0x00)",
        }
    }
}

/// What a valid image file holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageInfo {
    pub format: ImageFormat,
    /// The header's viewport (0xFF, 0x00); for 0xD9 files, which have no header, the bounding
    /// box of the records' x ranges and y values.
    pub viewport: Viewport,
    /// Rows stored: the viewport's height, or the number of 0xD9 records.
    pub rows: u32,
    /// Whether every pixel of the viewport is stored. Always true for 0xFF and 0x00; a 0xD9 file
    /// can leave gaps (rows missing, or records narrower than the bounding box), whose pixels a
    /// decoder leaves alone.
    pub complete: bool,
}

impl ImageInfo {
    /// The viewport's width, 1..=65536.
    pub const fn width(&self) -> u32 {
        (self.viewport.x2 - self.viewport.x1) as u32 + 1
    }

    /// The viewport's height, 1..=65536.
    pub const fn height(&self) -> u32 {
        (self.viewport.y2 - self.viewport.y1) as u32 + 1
    }

    pub const fn pixel_count(&self) -> u64 {
        self.width() as u64 * self.height() as u64
    }
}

/// One piece of a decoded image, in image coordinates: `x` from the viewport's left edge, `row`
/// from its top (row 0 is screen y = vy2), as [`PixelSink`] has them. Each row's pieces come
/// left to right and end with [`DecodedEvent::RowDone`]; rows come in file order, top first.
/// Slices borrow straight from the file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecodedEvent<'a> {
    /// `pixels.len()` palette indices from column `x`: a whole 0xFF row, or a literal packet.
    Indices { x: u16, row: u16, pixels: &'a [u8] },
    /// `count` pixels of one palette index from column `x`: a run packet.
    Fill { x: u16, row: u16, count: u16, index: u8 },
    /// A whole RGB row from column `x`: R, G, B per pixel, `bytes.len() / 3` pixels.
    Rgb { x: u16, row: u16, bytes: &'a [u8] },
    /// Row `row` (one 0xD9 record, or one header row) is finished.
    RowDone { row: u16 },
}

/// The format of `bytes`, from its first byte.
pub fn identify(bytes: &[u8]) -> Result<ImageFormat, FormatError> {
    let id = *bytes.first().ok_or(FormatError::new(FormatErrorKind::Empty, 0))?;
    ImageFormat::from_id(id).ok_or(FormatError::new(FormatErrorKind::UnknownId { id }, 0))
}

/// Validates a whole image file and says what it holds, without delivering pixels.
pub fn inspect(bytes: &[u8]) -> Result<ImageInfo, FormatError> {
    walk(bytes, &mut |_| {})
}

/// Decodes an image file of any of the three formats, delivering it piece by piece to `visit`.
///
/// The file is validated completely before the first event, so `visit` sees either all of a
/// valid file or nothing. Needs no buffer: pixel slices borrow from `bytes`.
pub fn decode<'a>(bytes: &'a [u8], visit: &mut impl FnMut(DecodedEvent<'a>)) -> Result<ImageInfo, FormatError> {
    let info = inspect(bytes)?;
    let (left, top) = (info.viewport.x1, info.viewport.y2);
    // `walk` reports absolute x and screen y; within the viewport both subtractions are exact.
    walk(bytes, &mut |event| {
        visit(match event {
            DecodedEvent::Indices { x, row, pixels } => DecodedEvent::Indices { x: x - left, row: top - row, pixels },
            DecodedEvent::Fill { x, row, count, index } => DecodedEvent::Fill { x: x - left, row: top - row, count, index },
            DecodedEvent::Rgb { x, row, bytes } => DecodedEvent::Rgb { x: x - left, row: top - row, bytes },
            DecodedEvent::RowDone { row } => DecodedEvent::RowDone { row: top - row },
        })
    })
}

/// Decodes a PGA file (0xD9 or 0xFF) into `sink` as palette indices, in image coordinates
/// (see [`DecodedEvent`]). An RGB file is an error ([`FormatErrorKind::NotIndexed`]). Pixels a
/// 0xD9 file does not cover are left alone.
pub fn decode_indices_into<S: PixelSink<u8> + ?Sized>(bytes: &[u8], sink: &mut S) -> Result<ImageInfo, FormatError> {
    if identify(bytes)? == ImageFormat::Rgb {
        return Err(FormatError::new(FormatErrorKind::NotIndexed, 0));
    }
    decode(bytes, &mut |event| match event {
        DecodedEvent::Indices { x, row, pixels } => sink.write_row(x, row, pixels),
        DecodedEvent::Fill { x, row, count, index } => sink.fill_row(x, row, count, index),
        DecodedEvent::Rgb { .. } => {}
        DecodedEvent::RowDone { row } => sink.row_done(row),
    })
}

/// Decodes any image file into `sink` as RGB pixels: RGB files as they are, PGA files through
/// `palette` (each 4-bit channel times 17). Pixels a 0xD9 file does not cover are left alone.
pub fn decode_rgb_into<S: PixelSink<Rgb888> + ?Sized>(bytes: &[u8], palette: &Palette, sink: &mut S) -> Result<ImageInfo, FormatError> {
    decode(bytes, &mut |event| match event {
        DecodedEvent::Indices { x, row, pixels } => {
            write_chunked(sink, x, row, pixels.len(), |i| pixels.get(i).map_or([0; 3], |index| palette.entry(*index).to_rgb888()))
        }
        DecodedEvent::Fill { x, row, count, index } => sink.fill_row(x, row, count, palette.entry(index).to_rgb888()),
        DecodedEvent::Rgb { x, row, bytes } => write_chunked(sink, x, row, bytes.len() / rgb::BYTES_PER_PIXEL, |i| {
            match bytes.get(i * rgb::BYTES_PER_PIXEL..i * rgb::BYTES_PER_PIXEL + rgb::BYTES_PER_PIXEL) {
                Some(&[r, g, b]) => [r, g, b],
                _ => [0; 3],
            }
        }),
        DecodedEvent::RowDone { row } => sink.row_done(row),
    })
}

/// Hands `count` converted pixels to `sink.write_row` through a small stack buffer.
fn write_chunked<S: PixelSink<Rgb888> + ?Sized>(sink: &mut S, x: u16, row: u16, count: usize, pixel: impl Fn(usize) -> Rgb888) {
    const CHUNK: usize = 32;
    let mut buffer = [[0u8; 3]; CHUNK];
    let mut done = 0;
    while done < count {
        let take = CHUNK.min(count - done);
        for (i, slot) in buffer[..take].iter_mut().enumerate() {
            *slot = pixel(done + i);
        }
        sink.write_row(x.saturating_add(done as u16), row, &buffer[..take]);
        done += take;
    }
}

/// Validates and walks a file, reporting events in the file's own coordinates (absolute x, and
/// screen y in the `row` fields).
fn walk<'a>(bytes: &'a [u8], visit: &mut impl FnMut(DecodedEvent<'a>)) -> Result<ImageInfo, FormatError> {
    match identify(bytes)? {
        ImageFormat::PgaCompressed => walk_records(bytes, visit),
        format @ (ImageFormat::PgaUncompressed | ImageFormat::Rgb) => walk_raw(bytes, format, visit),
    }
}

/// 0xFF and 0x00: a 9-byte header, then exactly width·height·(1 or 3) bytes.
fn walk_raw<'a>(bytes: &'a [u8], format: ImageFormat, visit: &mut impl FnMut(DecodedEvent<'a>)) -> Result<ImageInfo, FormatError> {
    let truncated_header = FormatError::new(FormatErrorKind::TruncatedHeader { needed: HEADER_LEN, available: bytes.len() }, bytes.len());
    let (Some(x1), Some(x2), Some(y1), Some(y2)) = (le16(bytes, 1), le16(bytes, 3), le16(bytes, 5), le16(bytes, 7)) else {
        return Err(truncated_header);
    };
    if x1 > x2 {
        return Err(FormatError::new(FormatErrorKind::ReversedRange { axis: Axis::X, low: x1, high: x2 }, 1));
    }
    if y1 > y2 {
        return Err(FormatError::new(FormatErrorKind::ReversedRange { axis: Axis::Y, low: y1, high: y2 }, 5));
    }
    let viewport = Viewport { x1, x2, y1, y2 };
    let bytes_per_pixel = if format == ImageFormat::Rgb { rgb::BYTES_PER_PIXEL } else { 1 };
    let width = usize::from(x2 - x1) + 1;
    let height = u32::from(y2 - y1) + 1;
    let row_len = width * bytes_per_pixel; // at most 3 · 65536
    let expected = HEADER_LEN as u64 + row_len as u64 * u64::from(height);
    let available = bytes.len();
    if (available as u64) < expected {
        return Err(FormatError::new(FormatErrorKind::TruncatedPixels { expected, available }, available));
    }
    if available as u64 > expected {
        // `expected` < `available`, so it fits a usize.
        return Err(FormatError::new(FormatErrorKind::TrailingBytes { expected, available }, expected as usize));
    }
    let truncated = FormatError::new(FormatErrorKind::TruncatedPixels { expected, available }, available);
    let mut rows = bytes.get(HEADER_LEN..).ok_or(truncated)?.chunks_exact(row_len);
    for y in (y1..=y2).rev() {
        let pixels = rows.next().ok_or(truncated)?;
        visit(if format == ImageFormat::Rgb {
            DecodedEvent::Rgb { x: x1, row: y, bytes: pixels }
        } else {
            DecodedEvent::Indices { x: x1, row: y, pixels }
        });
        visit(DecodedEvent::RowDone { row: y });
    }
    Ok(ImageInfo { format, viewport, rows: height, complete: true })
}

/// 0xD9: records `0xD9, y, x1, x2, packets…` until the end of the file, y strictly decreasing.
fn walk_records<'a>(bytes: &'a [u8], visit: &mut impl FnMut(DecodedEvent<'a>)) -> Result<ImageInfo, FormatError> {
    let mut pos = 0;
    let mut first: Option<(u16, u16, u16)> = None; // the first record's y, x1, x2
    let mut previous_y = 0u16;
    let (mut x_min, mut x_max, mut y_min) = (u16::MAX, 0u16, 0u16);
    let mut same_range = true;
    let mut rows = 0u32;
    while let Some(&id) = bytes.get(pos) {
        if id != pga_compressed::ID {
            return Err(FormatError::new(FormatErrorKind::NotARecord { found: id }, pos));
        }
        let (Some(y), Some(x1), Some(x2)) = (le16(bytes, pos + 1), le16(bytes, pos + 3), le16(bytes, pos + 5)) else {
            let kind = FormatErrorKind::TruncatedHeader { needed: pga_compressed::RECORD_HEADER_LEN, available: bytes.len() - pos };
            return Err(FormatError::new(kind, bytes.len()));
        };
        if x1 > x2 {
            return Err(FormatError::new(FormatErrorKind::ReversedRange { axis: Axis::X, low: x1, high: x2 }, pos + 3));
        }
        match first {
            None => first = Some((y, x1, x2)),
            Some((_, first_x1, first_x2)) => {
                if y >= previous_y {
                    return Err(FormatError::new(FormatErrorKind::RowOrder { y, previous: previous_y }, pos + 1));
                }
                same_range &= (x1, x2) == (first_x1, first_x2);
            }
        }
        previous_y = y;
        let width = u32::from(x2 - x1) + 1;
        let mut decoded = 0u32;
        let mut p = pos + pga_compressed::RECORD_HEADER_LEN;
        while decoded < width {
            let truncated = FormatError::new(FormatErrorKind::TruncatedPacket { y, decoded, width }, bytes.len());
            let count = *bytes.get(p).ok_or(truncated)?;
            let pixels: u16 = if count < 128 { u16::from(count) + 1 } else { u16::from(count) - 127 };
            let remaining = width - decoded;
            if u32::from(pixels) > remaining {
                return Err(FormatError::new(FormatErrorKind::PacketPastRow { y, pixels, remaining }, p));
            }
            // x1 + decoded <= x2, so this fits a u16.
            let x = x1 + decoded as u16;
            if count < 128 {
                let index = *bytes.get(p + 1).ok_or(truncated)?;
                visit(DecodedEvent::Fill { x, row: y, count: pixels, index });
                p += 2;
            } else {
                let literal = bytes.get(p + 1..p + 1 + usize::from(pixels)).ok_or(truncated)?;
                visit(DecodedEvent::Indices { x, row: y, pixels: literal });
                p += 1 + usize::from(pixels);
            }
            decoded += u32::from(pixels);
        }
        visit(DecodedEvent::RowDone { row: y });
        x_min = x_min.min(x1);
        x_max = x_max.max(x2);
        y_min = y;
        rows += 1;
        pos = p;
    }
    // `identify` saw a 0xD9 first byte, so there was at least one record.
    let (y_max, _, _) = first.ok_or(FormatError::new(FormatErrorKind::Empty, 0))?;
    let viewport = Viewport { x1: x_min, x2: x_max, y1: y_min, y2: y_max };
    let complete = same_range && rows == u32::from(y_max - y_min) + 1;
    Ok(ImageInfo { format: ImageFormat::PgaCompressed, viewport, rows, complete })
}
