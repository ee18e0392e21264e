//! The OLED picture: QEMU's monitor `screendump` writes the lm3s6965evb screen as a 512x256
//! PPM in which OLED pixel (x, y) is the 4x4 block at (4x, 4y) and grey level g shows as
//! 17·g (shared/research/qemu.md, "Capturing the screen"). We keep one sample per block as an
//! 8-bit grey PNG of the OLED's own size.

use std::path::Path;

/// How many screen pixels one OLED pixel covers in each direction.
pub const SCALE: usize = 4;

/// An 8-bit grey image, rows top first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GreyImage {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<u8>,
}

/// Reads a binary PPM (P6, maxval 255) and returns its pixels as RGB triples.
fn parse_ppm(bytes: &[u8]) -> Result<(usize, usize, &[u8]), String> {
    // Header: "P6", width, height, maxval, separated by whitespace (comments unsupported: QEMU
    // writes none), then one whitespace byte and the raster.
    let mut fields = Vec::new();
    let mut position = 0;
    while fields.len() < 4 {
        while position < bytes.len() && bytes[position].is_ascii_whitespace() {
            position += 1;
        }
        let start = position;
        while position < bytes.len() && !bytes[position].is_ascii_whitespace() {
            position += 1;
        }
        if start == position {
            return Err("truncated PPM header".into());
        }
        fields.push(std::str::from_utf8(&bytes[start..position]).map_err(|_| "bad PPM header")?.to_owned());
    }
    position += 1;
    if fields[0] != "P6" || fields[3] != "255" {
        return Err(format!("expected a P6 PPM with maxval 255, found {} / {}", fields[0], fields[3]));
    }
    let width: usize = fields[1].parse().map_err(|_| "bad PPM width")?;
    let height: usize = fields[2].parse().map_err(|_| "bad PPM height")?;
    let raster = bytes.get(position..position + width * height * 3).ok_or("truncated PPM raster")?;
    Ok((width, height, raster))
}

/// The OLED picture from a `screendump` PPM: the top-left sample of each 4x4 block, grey from
/// the green channel (the three are equal).
pub fn downsample_screendump(ppm: &[u8]) -> Result<GreyImage, String> {
    let (width, height, raster) = parse_ppm(ppm)?;
    if width % SCALE != 0 || height % SCALE != 0 {
        return Err(format!("screendump is {width}x{height}, not a multiple of {SCALE}"));
    }
    let (oled_width, oled_height) = (width / SCALE, height / SCALE);
    let mut pixels = Vec::with_capacity(oled_width * oled_height);
    for y in 0..oled_height {
        for x in 0..oled_width {
            let offset = ((y * SCALE) * width + x * SCALE) * 3;
            pixels.push(raster[offset + 1]);
        }
    }
    Ok(GreyImage { width: oled_width, height: oled_height, pixels })
}

pub fn write_png(path: &Path, image: &GreyImage) -> Result<(), String> {
    let file = std::fs::File::create(path).map_err(|error| format!("{}: {error}", path.display()))?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), image.width as u32, image.height as u32);
    encoder.set_color(png::ColorType::Grayscale);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|error| format!("{}: {error}", path.display()))?;
    writer.write_image_data(&image.pixels).map_err(|error| format!("{}: {error}", path.display()))?;
    writer.finish().map_err(|error| format!("{}: {error}", path.display()))
}

/// Reads an 8-bit grey PNG such as `oled.png`.
pub fn read_png(path: &Path) -> Result<GreyImage, String> {
    let file = std::fs::File::open(path).map_err(|error| format!("{}: {error}", path.display()))?;
    let mut reader = png::Decoder::new(std::io::BufReader::new(file)).read_info().map_err(|error| format!("{}: {error}", path.display()))?;
    let info = reader.info();
    if info.color_type != png::ColorType::Grayscale || info.bit_depth != png::BitDepth::Eight {
        return Err(format!("{}: not an 8-bit grey PNG", path.display()));
    }
    let (width, height) = (info.width as usize, info.height as usize);
    let mut pixels = vec![0; reader.output_buffer_size().ok_or("PNG too large")?];
    reader.next_frame(&mut pixels).map_err(|error| format!("{}: {error}", path.display()))?;
    pixels.truncate(width * height);
    Ok(GreyImage { width, height, pixels })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn screendump_blocks_become_oled_pixels() {
        // An 8x4 screen (2x1 OLED pixels): the left block grey 3 (51), the right grey 15 (255).
        let mut ppm = b"P6\n8 4\n255\n".to_vec();
        for _y in 0..4 {
            for x in 0..8 {
                let value = if x < 4 { 51 } else { 255 };
                ppm.extend_from_slice(&[value, value, value]);
            }
        }
        let image = downsample_screendump(&ppm).unwrap();
        assert_eq!(image, GreyImage { width: 2, height: 1, pixels: vec![51, 255] });
    }

    #[test]
    fn png_round_trips() {
        let image = GreyImage { width: 3, height: 2, pixels: vec![0, 17, 34, 51, 238, 255] };
        let path = std::env::temp_dir().join(format!("xtask-oled-test-{}.png", std::process::id()));
        write_png(&path, &image).unwrap();
        assert_eq!(read_png(&path).unwrap(), image);
        let _ = std::fs::remove_file(&path);
    }
}
