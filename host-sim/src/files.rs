//! Files on the desktop: PNGs, and the thesis's image and look-up-table formats through
//! `microtrace::formats`. Every writer is atomic: the bytes go to a temporary file in the target's
//! directory, which is renamed into place only when complete, so a failure never leaves a
//! partial or truncated output (and never damages an existing file of that name).
#![allow(dead_code)]

use std::fs::{self, File, OpenOptions};
use std::io::{self, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Mutex, MutexGuard};

use microtrace::formats::{self, lut, pga_compressed, pga_uncompressed, rgb, DecodedEvent, FormatError};
use microtrace::model::Rgb888;
use microtrace::model::Viewport;
use microtrace::model::Palette;

/// The largest image `decode_image_file` accepts: the `--size` limit, 8192 x 8192 pixels. A 0xD9
/// file's bounding box is not bounded by its length (two short records far apart), so this
/// keeps a small bogus file from asking for gigabytes.
pub const MAX_DECODED_PIXELS: u64 = 8192 * 8192;

fn invalid_input(message: String) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidInput, message)
}

fn invalid_data(error: FormatError) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, error)
}

/// Every temporary file this process has open, for [`remove_temporaries_on_interrupt`]. A file
/// is listed from its creation until it is renamed into place or removed; the rename happens
/// with the list locked, so an interrupt sees each file either listed or in place, whole.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn temporaries() -> MutexGuard<'static, Vec<PathBuf>> {
    TEMPORARIES.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// What `microtrace` says when Ctrl-C stops it (exit status 130, as a shell reports SIGINT).
pub const INTERRUPTED: &str = "microtrace: interrupted (Ctrl-C): stopped, no output file written or left half-written";

/// Installs the Ctrl-C (SIGINT) handler: it removes every temporary file of this process, says
/// [`INTERRUPTED`] on stderr and exits with status 130. Files already renamed into place are
/// complete; the one being written is not left behind, and no target file is touched.
pub fn remove_temporaries_on_interrupt() {
    let installed = ctrlc::set_handler(|| {
        let mut live = temporaries();
        for path in live.drain(..) {
            let _ = fs::remove_file(path);
        }
        eprintln!("\n{INTERRUPTED}");
        // The list stays locked: no rename can complete after this point.
        std::process::exit(130);
    });
    if let Err(error) = installed {
        eprintln!("microtrace: cannot catch Ctrl-C ({error}); an interrupted write may leave a temporary file");
    }
}

/// Removes the temporary file when dropped, unless it was renamed into place; this also
/// covers a panic inside the caller's writer.
struct TempFile {
    path: PathBuf,
    renamed: bool,
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.renamed {
            let _ = fs::remove_file(&self.path);
            temporaries().retain(|live| *live != self.path);
        }
    }
}

/// Creates a fresh hidden temporary file next to `path`.
fn create_temp_next_to(path: &Path) -> io::Result<(File, TempFile)> {
    static COUNTER: AtomicU32 = AtomicU32::new(0);
    let name = path.file_name().ok_or_else(|| invalid_input(format!("{} is not a file name", path.display())))?;
    let directory = match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    };
    loop {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let mut temp_name = std::ffi::OsString::from(".");
        temp_name.push(name);
        temp_name.push(format!(".{}.{n}.tmp", std::process::id()));
        let temp = directory.join(temp_name);
        // Listed before it exists, so that an interrupt between the two cannot miss it.
        temporaries().push(temp.clone());
        match OpenOptions::new().write(true).create_new(true).open(&temp) {
            Ok(file) => return Ok((file, TempFile { path: temp, renamed: false })),
            Err(error) => {
                temporaries().retain(|live| *live != temp);
                if error.kind() == io::ErrorKind::AlreadyExists && n % 1000 != 999 {
                    continue;
                }
                return Err(error);
            }
        }
    }
}

/// Writes `path` through `write`, all or nothing: into a temporary file in the same directory,
/// flushed and synced, then renamed over `path`. On any error (or a panic in `write`) the
/// temporary file is removed and `path` is left as it was.
pub fn write_atomically(path: &Path, write: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> io::Result<()> {
    let (file, mut temp) = create_temp_next_to(path)?;
    let mut writer = BufWriter::new(file);
    write(&mut writer)?;
    let file = writer.into_inner().map_err(|error| error.into_error())?;
    file.sync_all()?;
    drop(file);
    let mut live = temporaries();
    fs::rename(&temp.path, path)?;
    live.retain(|listed| *listed != temp.path);
    temp.renamed = true;
    Ok(())
}

/// `width` x `height` as a pixel count, checking that `len` pixels were given.
fn check_size(width: u32, height: u32, len: usize, what: &str) -> io::Result<()> {
    let expected = u64::from(width) * u64::from(height);
    if width == 0 || height == 0 {
        return Err(invalid_input(format!("{what}: an image of {width} x {height} pixels is empty")));
    }
    if expected != len as u64 {
        return Err(invalid_input(format!("{what}: {width} x {height} needs {expected} pixels, got {len}")));
    }
    Ok(())
}

/// The PNG encoder's settings for every image the command writes: `Compression::Fast` (the
/// png crate's fdeflate, with its adaptive choice of row filter). Measured on the thesis scenes
/// (docs/desktop-speed.md): the 528x480 snooker frame took 11.4 ms to encode as RGB with the
/// default `Balanced` (miniz_oxide), a sixth of the whole `render` process; as an indexed PNG
/// with `Fast` it takes 0.3 ms and is smaller (18.9 KB against 20.3 KB).
const PNG_COMPRESSION: png::Compression = png::Compression::Fast;

/// Writes a PNG of `data` (rows top first, no padding) in `colour`: 8 bits per channel, or per
/// index with `palette` (256 RGB triples) for `ColorType::Indexed`.
fn write_png(path: &Path, width: u16, height: u16, colour: png::ColorType, palette: Option<&[u8]>, data: &[u8]) -> io::Result<()> {
    write_atomically(path, |out| {
        let mut encoder = png::Encoder::new(out, u32::from(width), u32::from(height));
        encoder.set_color(colour);
        encoder.set_depth(png::BitDepth::Eight);
        if let Some(palette) = palette {
            encoder.set_palette(palette);
        }
        encoder.set_compression(PNG_COMPRESSION);
        let mut writer = encoder.write_header()?;
        writer.write_image_data(data)?;
        writer.finish()?;
        Ok(())
    })
}

/// An indexed (palette) PNG of palette indices (rows top first): one byte a pixel, as on the
/// 256-colour PGA, with the look-up table as the PNG palette (every 4-bit channel times 17).
/// Any decoder that expands the palette gets the same 8-bit RGB pixels as the RGB PNG this
/// wrote before; the file holds a third of the data, so it is far quicker to encode.
pub fn write_png_indexed(path: &Path, width: u16, height: u16, indices: &[u8], palette: &Palette) -> io::Result<()> {
    check_size(width.into(), height.into(), indices.len(), "indexed PNG")?;
    let table: Vec<u8> = palette.entries.iter().flat_map(|entry| entry.to_rgb888()).collect();
    write_png(path, width, height, png::ColorType::Indexed, Some(&table), indices)
}

/// An 8-bit RGB PNG (rows top first).
pub fn write_png_rgb(path: &Path, width: u16, height: u16, rgb: &[Rgb888]) -> io::Result<()> {
    check_size(width.into(), height.into(), rgb.len(), "RGB PNG")?;
    write_png(path, width, height, png::ColorType::Rgb, None, rgb.as_flattened())
}

/// Reads any 8- or 16-bit PNG back as RGB (grey expanded, alpha and low bytes dropped):
/// width, height and the pixels, rows top first. For tests and comparisons.
pub fn read_png_rgb(path: &Path) -> io::Result<(u32, u32, Vec<Rgb888>)> {
    let mut decoder = png::Decoder::new(BufReader::new(File::open(path)?));
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info()?;
    let size = reader.output_buffer_size().ok_or_else(|| io::Error::new(io::ErrorKind::InvalidData, "PNG too large"))?;
    let mut buffer = vec![0; size];
    let info = reader.next_frame(&mut buffer)?;
    let channels = match info.color_type {
        png::ColorType::Grayscale => 1,
        png::ColorType::GrayscaleAlpha => 2,
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        png::ColorType::Indexed => {
            return Err(io::Error::new(io::ErrorKind::InvalidData, "PNG palette was not expanded"));
        }
    };
    let mut pixels = Vec::with_capacity(info.width as usize * info.height as usize);
    for line in buffer.chunks(info.line_size).take(info.height as usize) {
        for pixel in line.chunks_exact(channels).take(info.width as usize) {
            pixels.push(if channels < 3 { [pixel[0]; 3] } else { [pixel[0], pixel[1], pixel[2]] });
        }
    }
    Ok((info.width, info.height, pixels))
}

/// The viewport's width and height, checking it is not reversed and that `len` pixels fit it.
fn viewport_size(viewport: Viewport, len: usize, what: &str) -> io::Result<(usize, usize)> {
    if viewport.x1 > viewport.x2 || viewport.y1 > viewport.y2 {
        return Err(invalid_input(format!("{what}: reversed viewport {viewport:?}")));
    }
    let width = usize::from(viewport.x2 - viewport.x1) + 1;
    let height = usize::from(viewport.y2 - viewport.y1) + 1;
    check_size(width as u32, height as u32, len, what)?;
    Ok((width, height))
}

/// The thesis's default file: one 0xD9 record per row, top row (y = vy2) first, each row
/// compressed by `linecompress`. `indices` holds the viewport's rows top first.
pub fn write_pga_compressed(path: &Path, viewport: Viewport, indices: &[u8]) -> io::Result<()> {
    let (width, _) = viewport_size(viewport, indices.len(), "PGA compressed file")?;
    let mut record = vec![0u8; pga_compressed::max_compressed_row_len(width)];
    write_atomically(path, |out| {
        for (row, y) in indices.chunks_exact(width).zip((viewport.y1..=viewport.y2).rev()) {
            let len = pga_compressed::compress_row(row, y, viewport.x1, viewport.x2, &mut record);
            if len == 0 {
                return Err(io::Error::other("row compression refused its input"));
            }
            out.write_all(&record[..len])?;
        }
        Ok(())
    })
}

/// The 0xFF file: the 9-byte header, then the indices as they are (rows top first).
pub fn write_pga_uncompressed(path: &Path, viewport: Viewport, indices: &[u8]) -> io::Result<()> {
    viewport_size(viewport, indices.len(), "PGA uncompressed file")?;
    write_atomically(path, |out| {
        out.write_all(&pga_uncompressed::write_header(viewport))?;
        out.write_all(indices)
    })
}

/// The 0x00 RGB file: the 9-byte header, then R, G, B per pixel (rows top first).
pub fn write_rgb_file(path: &Path, viewport: Viewport, rgb: &[Rgb888]) -> io::Result<()> {
    viewport_size(viewport, rgb.len(), "RGB file")?;
    write_atomically(path, |out| {
        out.write_all(&rgb::write_header(viewport))?;
        out.write_all(rgb.as_flattened())
    })
}

/// The 512-byte look-up-table file (`savecolors`).
pub fn write_lut_file(path: &Path, palette: &Palette) -> io::Result<()> {
    let bytes = lut::encode_lut(palette);
    write_atomically(path, |out| out.write_all(&bytes))
}

/// Reads a look-up-table file (`readcolors`); anything but 512 bytes is an error.
pub fn read_lut_file(path: &Path) -> io::Result<Palette> {
    lut::decode_lut(&fs::read(path)?).map_err(invalid_data)
}

/// An image file read back.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DecodedImage {
    pub width: u16,
    pub height: u16,
    /// The pixels as RGB, rows top first: RGB files as stored, PGA files through the palette.
    pub rgb: Vec<Rgb888>,
    /// The palette indices for the PGA formats (0xD9, 0xFF); `None` for RGB files.
    pub indices: Option<Vec<u8>>,
    /// The file's format.
    pub format: formats::ImageFormat,
    /// The file's viewport (for 0xD9 files, the bounding box of the records).
    pub viewport: Viewport,
}

/// Reads any of the three image formats. Indexed files go through `palette` (default
/// [`Palette::grey`]). Pixels a 0xD9 file leaves uncovered (missing rows or narrower records)
/// are index 0 (RGB files are always complete). A malformed file is an `InvalidData` error
/// whose message says what is wrong and at which byte offset.
pub fn decode_image_file(path: &Path, palette: Option<&Palette>) -> io::Result<DecodedImage> {
    let bytes = fs::read(path)?;
    let info = formats::inspect(&bytes).map_err(invalid_data)?;
    let too_large = || {
        io::Error::new(io::ErrorKind::InvalidData, format!("image of {} x {} pixels is too large to decode", info.width(), info.height()))
    };
    let (Ok(width), Ok(height)) = (u16::try_from(info.width()), u16::try_from(info.height())) else {
        return Err(too_large());
    };
    if info.pixel_count() > MAX_DECODED_PIXELS {
        return Err(too_large());
    }
    let (w, count) = (usize::from(width), info.pixel_count() as usize);
    let grey = Palette::grey();
    let palette = palette.unwrap_or(&grey);

    let mut indices = vec![0u8; if info.format.is_indexed() { count } else { 0 }];
    let mut rgb = vec![[0u8; 3]; if info.format.is_indexed() { 0 } else { count }];
    formats::decode(&bytes, &mut |event| match event {
        DecodedEvent::Indices { x, row, pixels } => {
            let start = usize::from(row) * w + usize::from(x);
            indices[start..start + pixels.len()].copy_from_slice(pixels);
        }
        DecodedEvent::Fill { x, row, count, index } => {
            let start = usize::from(row) * w + usize::from(x);
            indices[start..start + usize::from(count)].fill(index);
        }
        DecodedEvent::Rgb { x, row, bytes } => {
            let start = usize::from(row) * w + usize::from(x);
            for (slot, pixel) in rgb[start..].iter_mut().zip(bytes.chunks_exact(3)) {
                *slot = [pixel[0], pixel[1], pixel[2]];
            }
        }
        DecodedEvent::RowDone { .. } => {}
    })
    .map_err(invalid_data)?;
    let indices = if info.format.is_indexed() {
        rgb = indices.iter().map(|&index| palette.entry(index).to_rgb888()).collect();
        Some(indices)
    } else {
        None
    };
    Ok(DecodedImage { width, height, rgb, indices, format: info.format, viewport: info.viewport })
}

#[cfg(test)]
mod tests {
    use super::*;
    use microtrace::formats::ImageFormat;
    use microtrace::model::Rgb4;

    /// A fresh, empty directory under the system's temp dir.
    fn scratch(name: &str) -> PathBuf {
        let directory = std::env::temp_dir().join(format!("microtrace-files-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&directory);
        fs::create_dir_all(&directory).unwrap();
        directory
    }

    fn entries(directory: &Path) -> Vec<String> {
        let mut names: Vec<String> =
            fs::read_dir(directory).unwrap().map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned()).collect();
        names.sort();
        names
    }

    /// A deterministic test image: runs and noise (xorshift32).
    fn test_indices(count: usize, seed: u32) -> Vec<u8> {
        let mut state = seed;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            state
        };
        let mut pixels = Vec::with_capacity(count);
        while pixels.len() < count {
            let value = next() as u8;
            let run = if next() % 3 == 0 { 1 + next() % 40 } else { 1 };
            for _ in 0..run {
                if pixels.len() < count {
                    pixels.push(value);
                }
            }
        }
        pixels
    }

    fn test_palette() -> Palette {
        let mut palette = Palette::grey();
        palette.set_group_up(1, Rgb4::new(15, 7, 0));
        palette.set_group_down(2, Rgb4::new(3, 9, 15));
        palette.entries[255] = Rgb4::new(1, 2, 3);
        palette
    }

    #[test]
    fn atomic_write_writes_the_whole_file_and_no_temp_is_left() {
        let directory = scratch("atomic-ok");
        let path = directory.join("out.bin");
        write_atomically(&path, |out| out.write_all(b"hello")).unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"hello");
        // Replacing an existing file.
        write_atomically(&path, |out| out.write_all(b"bye")).unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"bye");
        assert_eq!(entries(&directory), ["out.bin"]);
    }

    #[test]
    fn atomic_write_leaves_no_file_on_error() {
        let directory = scratch("atomic-error");
        let path = directory.join("out.bin");
        let error = write_atomically(&path, |out| {
            out.write_all(&[7; 100_000])?;
            Err(io::Error::other("disk on fire"))
        })
        .unwrap_err();
        assert_eq!(error.to_string(), "disk on fire");
        assert!(entries(&directory).is_empty(), "{:?}", entries(&directory));

        // An existing file survives a failed rewrite untouched.
        fs::write(&path, b"original").unwrap();
        write_atomically(&path, |out| {
            out.write_all(b"partial")?;
            Err(io::Error::other("no"))
        })
        .unwrap_err();
        assert_eq!(fs::read(&path).unwrap(), b"original");
        assert_eq!(entries(&directory), ["out.bin"]);

        // A panic in the writer also cleans up.
        let result = std::panic::catch_unwind(|| {
            let _ = write_atomically(&directory.join("panic.bin"), |out| {
                out.write_all(b"x").unwrap();
                panic!("writer panicked");
            });
        });
        assert!(result.is_err());
        assert_eq!(entries(&directory), ["out.bin"]);
    }

    #[test]
    fn atomic_write_into_a_missing_directory_fails_cleanly() {
        let directory = scratch("atomic-missing");
        let path = directory.join("no-such-directory").join("out.png");
        assert!(write_atomically(&path, |out| out.write_all(b"x")).is_err());
        assert!(entries(&directory).is_empty());
        // A directory in the way: the rename fails and the temp file goes.
        fs::create_dir(directory.join("taken")).unwrap();
        assert!(write_atomically(&directory.join("taken"), |out| out.write_all(b"x")).is_err());
        assert_eq!(entries(&directory), ["taken"]);
    }

    #[test]
    fn wrong_sizes_are_rejected_before_anything_is_written() {
        let directory = scratch("sizes");
        let viewport = Viewport { x1: 0, x2: 3, y1: 0, y2: 2 };
        let path = directory.join("x");
        assert_eq!(write_png_indexed(&path, 4, 3, &[0; 11], &Palette::grey()).unwrap_err().kind(), io::ErrorKind::InvalidInput);
        assert!(write_png_rgb(&path, 0, 3, &[]).is_err());
        assert!(write_pga_compressed(&path, viewport, &[0; 13]).is_err());
        assert!(write_pga_uncompressed(&path, Viewport { x1: 4, x2: 3, y1: 0, y2: 0 }, &[0; 12]).is_err());
        assert!(write_rgb_file(&path, viewport, &[[0; 3]; 3]).is_err());
        assert!(entries(&directory).is_empty());
    }

    #[test]
    fn png_round_trips() {
        let directory = scratch("png");
        let palette = test_palette();
        let indices = test_indices(37 * 23, 1);
        let path = directory.join("indexed.png");
        write_png_indexed(&path, 37, 23, &indices, &palette).unwrap();
        let (width, height, pixels) = read_png_rgb(&path).unwrap();
        assert_eq!((width, height), (37, 23));
        let expected: Vec<Rgb888> = indices.iter().map(|&i| palette.entry(i).to_rgb888()).collect();
        assert_eq!(pixels, expected);
        assert!(pixels.iter().all(|p| p.iter().all(|c| c % 17 == 0)));

        let rgb: Vec<Rgb888> = (0..50 * 7).map(|i: u32| [i as u8, (i * 7) as u8, (i * 13) as u8]).collect();
        let path = directory.join("rgb.png");
        write_png_rgb(&path, 50, 7, &rgb).unwrap();
        assert_eq!(read_png_rgb(&path).unwrap(), (50, 7, rgb));
        assert_eq!(entries(&directory), ["indexed.png", "rgb.png"]);
    }

    #[test]
    fn pga_files_round_trip_and_decode_through_the_palette() {
        let directory = scratch("pga");
        let palette = test_palette();
        let viewport = Viewport { x1: 10, x2: 76, y1: 200, y2: 240 };
        let indices = test_indices(67 * 41, 2);
        let expected_rgb: Vec<Rgb888> = indices.iter().map(|&i| palette.entry(i).to_rgb888()).collect();
        let compressed = directory.join("image.pga");
        let uncompressed = directory.join("image.ff");
        write_pga_compressed(&compressed, viewport, &indices).unwrap();
        write_pga_uncompressed(&uncompressed, viewport, &indices).unwrap();
        let raw = fs::read(&uncompressed).unwrap();
        assert_eq!(raw.len(), 9 + 67 * 41);
        assert_eq!(&raw[..9], &[0xFF, 10, 0, 76, 0, 200, 0, 240, 0]);
        assert_eq!(&raw[9..], &indices[..]);
        let packed = fs::read(&compressed).unwrap();
        assert_eq!(&packed[..7], &[0xD9, 240, 0, 10, 0, 76, 0], "top row first");
        assert!(packed.len() < raw.len());

        for (path, format) in [(&compressed, ImageFormat::PgaCompressed), (&uncompressed, ImageFormat::PgaUncompressed)] {
            let image = decode_image_file(path, Some(&palette)).unwrap();
            assert_eq!((image.width, image.height, image.format, image.viewport), (67, 41, format, viewport));
            assert_eq!(image.indices.as_deref(), Some(&indices[..]));
            assert_eq!(image.rgb, expected_rgb);
            // The default palette is grey ramps.
            let grey = decode_image_file(path, None).unwrap();
            assert_eq!(grey.rgb[0], [(indices[0] % 16) * 17; 3]);
        }
    }

    #[test]
    fn compressed_file_is_the_records_of_linecompress() {
        let directory = scratch("pga-bytes");
        // 7 x 2, rows top first: [5,5,5,1,2,3,3] at y = 1, [9; 7] at y = 0.
        let path = directory.join("tiny.pga");
        let viewport = Viewport { x1: 0, x2: 6, y1: 0, y2: 1 };
        write_pga_compressed(&path, viewport, &[5, 5, 5, 1, 2, 3, 3, 9, 9, 9, 9, 9, 9, 9]).unwrap();
        assert_eq!(
            fs::read(&path).unwrap(),
            [0xD9, 1, 0, 0, 0, 6, 0, 0x02, 5, 0x81, 1, 2, 0x01, 3, 0xD9, 0, 0, 0, 0, 6, 0, 0x06, 9]
        );
    }

    #[test]
    fn rgb_file_round_trips() {
        let directory = scratch("rgb");
        let viewport = Viewport { x1: 0, x2: 30, y1: 5, y2: 16 };
        let rgb: Vec<Rgb888> = test_indices(31 * 12 * 3, 3).chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
        let path = directory.join("image.rgb");
        write_rgb_file(&path, viewport, &rgb).unwrap();
        let bytes = fs::read(&path).unwrap();
        assert_eq!(&bytes[..9], &[0x00, 0, 0, 30, 0, 5, 0, 16, 0]);
        assert_eq!(bytes.len(), 9 + 3 * 31 * 12);
        let image = decode_image_file(&path, Some(&test_palette())).unwrap();
        assert_eq!((image.width, image.height, image.format), (31, 12, ImageFormat::Rgb));
        assert_eq!(image.indices, None);
        assert_eq!(image.rgb, rgb);
    }

    #[test]
    fn lut_file_round_trips() {
        let directory = scratch("lut");
        let path = directory.join("colours.lut");
        let palette = test_palette();
        write_lut_file(&path, &palette).unwrap();
        let bytes = fs::read(&path).unwrap();
        assert_eq!(bytes.len(), 512);
        assert_eq!(&bytes[510..], &[0x23, 0x01]);
        assert_eq!(read_lut_file(&path).unwrap(), palette);
        fs::write(&path, &bytes[..100]).unwrap();
        let error = read_lut_file(&path).unwrap_err();
        assert_eq!(error.kind(), io::ErrorKind::InvalidData);
        assert!(error.to_string().contains("512 bytes"), "{error}");
    }

    #[test]
    fn bad_image_files_are_errors_that_say_where() {
        let directory = scratch("bad");
        let path = directory.join("bad.pga");
        fs::write(&path, b"\x42not an image").unwrap();
        let error = decode_image_file(&path, None).unwrap_err();
        assert_eq!(error.kind(), io::ErrorKind::InvalidData);
        assert!(error.to_string().contains("0x42") && error.to_string().contains("byte offset 0"), "{error}");

        // A record whose packet overruns its row.
        fs::write(&path, [0xD9, 7, 0, 3, 0, 5, 0, 0x03, 4]).unwrap();
        let error = decode_image_file(&path, None).unwrap_err();
        assert!(error.to_string().contains("runs past the end of row y = 7") && error.to_string().contains("offset 7"), "{error}");

        // Two tiny records 65535 rows apart claim a huge bounding box.
        fs::write(&path, [0xD9, 0xFF, 0xFF, 0, 0, 0, 0, 0, 1, 0xD9, 0, 0, 0, 0, 0, 0, 0, 1]).unwrap();
        let error = decode_image_file(&path, None).unwrap_err();
        assert!(error.to_string().contains("too large"), "{error}");

        assert_eq!(decode_image_file(&directory.join("missing"), None).unwrap_err().kind(), io::ErrorKind::NotFound);
    }

    #[test]
    fn uncovered_pixels_of_a_sparse_compressed_file_are_index_zero() {
        let directory = scratch("sparse");
        let path = directory.join("sparse.pga");
        // y = 2, x 1..2; y = 0, x 0..0 (row 1 missing).
        fs::write(&path, [0xD9, 2, 0, 1, 0, 2, 0, 0x01, 5, 0xD9, 0, 0, 0, 0, 0, 0, 0x00, 6]).unwrap();
        let image = decode_image_file(&path, None).unwrap();
        assert_eq!((image.width, image.height), (3, 3));
        assert_eq!(image.indices.unwrap(), [0, 5, 5, 0, 0, 0, 6, 0, 0]);
    }
}
