//! The Raspberry Pi Pico examples' images run: each UF2 file (the bytes a user drags onto the
//! Pico; `xtask::uf2`, written beside the ELF, which names the functions in the harness's
//! messages) boots in the rp2040js emulator from the RP2040's boot ROM, through boot2, to its
//! vector table, renders,
//! and drives its display over the bus; the harness (`tests/rp2040/run-pico.mjs`) models the
//! display on that bus and hands back what the display holds. Each picture must equal, bit for
//! bit, the host's render of the same scene through the same display mapping (the core's
//! `RowDisplaySink` with the example's colour map):
//! - `pico-ssd1306`: an SSD1306 at 0x3C on I2C0 (GP4, GP5), its command and data stream decoded
//!   into the 128x64 page memory (byte `page * 128 + x`, bit `k` the dot at row `8 * page + k`,
//!   1 lit), against the host's error-diffused dots (`LutLuma`, `ErrorDiffusion`: what
//!   `microtrace render --display ssd1306` writes);
//! - `pico-st7789`: an ST7789 on SPI0 with its DC pin, CASET/RASET/RAMWR decoded into a 240x240
//!   RGB565 picture (each pixel big-endian, as sent).
//!
//! The emulated cycles to the last display byte are printed: the Cortex-M0+ cost of a frame
//! (the emulator models no flash or I2C/SPI wait states; the examples' READMEs quote them).
//!
//! Needs Node.js and rp2040js (`scripts/setup.sh` installs both) and the chip's boot ROM,
//! `../shared/rp2040/bootrom-b1.bin` beside the repository (its README says where it comes from);
//! without them the test fails and says which is missing.

use std::path::{Path, PathBuf};

use embedded_graphics::pixelcolor::raw::RawU16;
use embedded_graphics::pixelcolor::{BinaryColor, Rgb565};
use embedded_graphics::prelude::*;
use microtrace::model::SceneDescription;
use microtrace::pixel::{ColourMap, ErrorDiffusion, FrameBuffer, LutColour, LutLuma, RowDisplaySink};
use microtrace::render::{render, Pga, Statistics, Whole};
use microtrace::scene::Scene;
use xtask::example::{self, Example};
use xtask::pico::{self, EmulatedRun};

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("the workspace").to_path_buf()
}

/// An in-memory picture the core's display sink draws into.
struct Picture<C> {
    width: u32,
    pixels: Vec<C>,
}

impl<C: PixelColor + Default> Picture<C> {
    fn new(width: u16, height: u16) -> Self {
        Self { width: u32::from(width), pixels: vec![C::default(); usize::from(width) * usize::from(height)] }
    }
}

impl<C> OriginDimensions for Picture<C> {
    fn size(&self) -> Size {
        Size::new(self.width, self.pixels.len() as u32 / self.width)
    }
}

impl<C: PixelColor> DrawTarget for Picture<C> {
    type Color = C;
    type Error = std::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
        for Pixel(point, colour) in pixels {
            if let (Ok(x), Ok(y)) = (u32::try_from(point.x), u32::try_from(point.y)) {
                if let Some(slot) = self.pixels.get_mut((y * self.width + x) as usize) {
                    *slot = colour;
                }
            }
        }
        Ok(())
    }
}

/// Snooker at the example's size, prepared in the example's number type (`f32`).
fn snooker(width: u16, height: u16) -> Scene<f32, 64> {
    let text = std::fs::read(workspace().join("scenes/snooker.mts")).unwrap();
    let mut description: SceneDescription<64> = microtrace::parser::parse(&text).unwrap();
    description.fit_to_size(width, height);
    Scene::<f32, 64>::prepare(&description).unwrap()
}

/// The host's render of `scene` through the core's display sink onto `target` with `map`.
fn host_picture<D: DrawTarget, M: ColourMap<Color = D::Color>>(scene: &Scene<f32, 64>, target: D, map: M) -> D {
    let (width, height) = (scene.viewport().width(), scene.viewport().height());
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let frame = FrameBuffer::new(&mut pixels, width, height).unwrap();
    let mut sink = RowDisplaySink::new(frame, target, map);
    render(scene, Pga, Whole, &mut sink, &mut Statistics::default());
    assert_eq!(sink.failed_rows, 0);
    sink.target
}

/// Runs `example`'s UF2 file in rp2040js (`xtask::pico`), failing with the harness's message.
fn emulate(example: &Example) -> EmulatedRun {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("pico");
    pico::run(example, &out).unwrap_or_else(|error| panic!("{error}"))
}

fn report(example: &Example, run: &EmulatedRun) {
    let at_125_mhz = run.cycles as f64 / 125e6;
    eprintln!("{}: {} emulated Cortex-M0+ cycles to the last display byte ({at_125_mhz:.3} s at 125 MHz)", example.folder, run.cycles);
    // The harness saw the core enter the example's `render` (the firmware report splits the
    // frame there), after the boot and before the last display byte.
    let entered = run.render_entered.unwrap_or_else(|| panic!("{}: no entry into `render` in:\n{}", example.folder, run.summary));
    assert!(entered > 0 && entered < run.cycles, "{}: `render` entered at cycle {entered} of {}", example.folder, run.cycles);
    eprintln!("{}: `render` entered at cycle {entered}", example.folder);
    // And it counted the instructions: fewer than the cycles (none takes less than one).
    let instructions = run.instructions.unwrap_or_else(|| panic!("{}: no instruction count in:\n{}", example.folder, run.summary));
    assert!(instructions > 0 && instructions <= run.cycles, "{}: {instructions} instructions in {} cycles", example.folder, run.cycles);
}

#[test]
fn the_pico_ssd1306_image_draws_the_host_picture_in_the_emulator() {
    let (width, height) = (128u16, 64u16);
    let run = emulate(&example::PICO_SSD1306);
    report(&example::PICO_SSD1306, &run);
    assert_eq!(run.display.len(), 1024, "the page memory:\n{}", run.summary);
    let scene = snooker(width, height);
    let expected = host_picture(&scene, ErrorDiffusion::<_, 128>::new(Picture::<BinaryColor>::new(width, height)), LutLuma::new(&scene.palette)).into_inner();
    let lit = |x: usize, y: usize| run.display[(y / 8) * usize::from(width) + x] >> (y % 8) & 1 == 1;
    let mut differing = Vec::new();
    for (offset, want) in expected.pixels.iter().enumerate() {
        let (x, y) = (offset % usize::from(width), offset / usize::from(width));
        if lit(x, y) != want.is_on() {
            differing.push((x, y));
        }
    }
    assert!(differing.is_empty(), "{} of the SSD1306's dots differ from the host's picture, the first at {:?}", differing.len(), &differing[..differing.len().min(8)]);
    // Snooker is neither blank nor all lit: the comparison compares something.
    let on = expected.pixels.iter().filter(|colour| colour.is_on()).count();
    assert!(on > 0 && on < expected.pixels.len(), "{on} dots lit");
}

#[test]
fn the_pico_st7789_image_draws_the_host_picture_in_the_emulator() {
    let (width, height) = (240u16, 240u16);
    let run = emulate(&example::PICO_ST7789);
    report(&example::PICO_ST7789, &run);
    assert_eq!(run.display.len(), usize::from(width) * usize::from(height) * 2, "the panel's memory:\n{}", run.summary);
    let scene = snooker(width, height);
    let expected = host_picture(&scene, Picture::<Rgb565>::new(width, height), LutColour::<Rgb565>::new(&scene.palette));
    let received = run.display.chunks_exact(2).map(|pair| u16::from_be_bytes([pair[0], pair[1]]));
    let differing: Vec<usize> = expected.pixels.iter().zip(received).enumerate().filter(|(_, (want, got))| RawU16::from(**want).into_inner() != *got).map(|(offset, _)| offset).collect();
    assert!(
        differing.is_empty(),
        "{} of the ST7789's pixels differ from the host's picture, the first at {:?}",
        differing.len(),
        differing.iter().take(8).map(|offset| (offset % usize::from(width), offset / usize::from(width))).collect::<Vec<_>>()
    );
    let colours: std::collections::BTreeSet<u16> = expected.pixels.iter().map(|colour| RawU16::from(*colour).into_inner()).collect();
    assert!(colours.len() >= 16, "{} colours", colours.len());
}
