//! `microtrace decode FILE --out IMAGE.png`: read any of the thesis's three image formats back.

use std::path::PathBuf;

use anyhow::Context;

use crate::files;

#[derive(clap::Args, Clone, Debug)]
pub struct DecodeArgs {
    /// A PGA compressed (0xD9), PGA uncompressed (0xFF) or RGB (0x00) image file.
    pub file: PathBuf,
    /// The look-up table for palette images (default: grey ramps).
    #[arg(long, value_name = "FILE")]
    pub lut: Option<PathBuf>,
    /// The PNG to write.
    #[arg(long, value_name = "IMAGE.png")]
    pub out: PathBuf,
}

pub fn run(args: DecodeArgs) -> anyhow::Result<()> {
    let palette = match &args.lut {
        Some(path) => Some(files::read_lut_file(path).with_context(|| format!("cannot read look-up table {}", path.display()))?),
        None => None,
    };
    let image = files::decode_image_file(&args.file, palette.as_ref()).with_context(|| format!("cannot decode {}", args.file.display()))?;
    files::write_png_rgb(&args.out, image.width, image.height, &image.rgb).with_context(|| format!("cannot write {}", args.out.display()))?;
    Ok(())
}
