//! What is wrong with a file, and where.

use core::fmt;

/// A malformed file: what is wrong ([`FormatErrorKind`]) and the byte offset where it was found
/// (for a truncated file, the file's length: where the missing bytes should have been).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FormatError {
    pub kind: FormatErrorKind,
    pub offset: usize,
}

impl FormatError {
    pub const fn new(kind: FormatErrorKind, offset: usize) -> Self {
        Self { kind, offset }
    }
}

/// The problems a decoder reports. Coordinates are the file's own (screen y, absolute x).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum FormatErrorKind {
    /// The file has no bytes at all.
    Empty,
    /// The first byte is none of 0xD9, 0xFF, 0x00.
    UnknownId { id: u8 },
    /// A header (9 bytes, or a 7-byte 0xD9 record header) is cut short.
    TruncatedHeader { needed: usize, available: usize },
    /// A range whose low end is above its high end (x1 > x2 or y1 > y2).
    ReversedRange { axis: Axis, low: u16, high: u16 },
    /// An uncompressed or RGB file shorter than its header's viewport needs.
    TruncatedPixels { expected: u64, available: usize },
    /// An uncompressed or RGB file longer than its header's viewport needs.
    TrailingBytes { expected: u64, available: usize },
    /// Between 0xD9 records, a byte that does not start another record.
    NotARecord { found: u8 },
    /// A 0xD9 record whose y is not below the previous record's (rows go top first, y down).
    RowOrder { y: u16, previous: u16 },
    /// The file ends inside row `y`'s packets, `decoded` of its `width` pixels in.
    TruncatedPacket { y: u16, decoded: u32, width: u32 },
    /// A packet of `pixels` pixels where only `remaining` are left in row `y`.
    PacketPastRow { y: u16, pixels: u16, remaining: u32 },
    /// A LUT file that is not exactly 512 bytes.
    LutLength { len: usize },
    /// An RGB file where palette indices were asked for.
    NotIndexed,
}

/// Which coordinate a [`FormatErrorKind::ReversedRange`] is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
}

impl fmt::Display for FormatErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::Empty => write!(f, "empty file"),
            Self::UnknownId { id } => {
                write!(f, "unknown format id byte 0x{id:02X} (expected 0xD9 compressed PGA, 0xFF uncompressed PGA or 0x00 RGB)")
            }
            Self::TruncatedHeader { needed, available } => {
                write!(f, "truncated header: needs {needed} bytes, only {available} left")
            }
            Self::ReversedRange { axis, low, high } => {
                let name = match axis {
                    Axis::X => 'x',
                    Axis::Y => 'y',
                };
                write!(f, "{name}1 = {low} is greater than {name}2 = {high}")
            }
            Self::TruncatedPixels { expected, available } => {
                write!(f, "truncated pixel data: the header's viewport needs a {expected}-byte file, it has {available} bytes")
            }
            Self::TrailingBytes { expected, available } => {
                write!(f, "{} unexpected bytes after the pixel data (the header's viewport needs {expected} bytes)", (available as u64).saturating_sub(expected))
            }
            Self::NotARecord { found } => write!(f, "expected a 0xD9 row record, found byte 0x{found:02X}"),
            Self::RowOrder { y, previous } => {
                write!(f, "row y = {y} does not come below the previous row y = {previous} (rows are stored top first)")
            }
            Self::TruncatedPacket { y, decoded, width } => {
                write!(f, "file ends inside row y = {y} after {decoded} of its {width} pixels")
            }
            Self::PacketPastRow { y, pixels, remaining } => {
                write!(f, "packet of {pixels} pixels runs past the end of row y = {y} ({remaining} pixels left)")
            }
            Self::LutLength { len } => write!(f, "a look-up-table file is 512 bytes, this one is {len}"),
            Self::NotIndexed => write!(f, "an RGB image has no palette indices"),
        }
    }
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at byte offset {}", self.kind, self.offset)
    }
}

impl core::error::Error for FormatError {}
