//! Every display path of the core, tested without hardware: the thesis's snooker scene rendered
//! through the core's `RowDisplaySink` into an in-memory display equals the host's image (the
//! framebuffer of palette indices) through that path's mapping, pixel for pixel:
//! - 4-bit grey (the lm3s6965evb's SSD0323 OLED): the LUT entry's Rec. 601 luma, 0..=15;
//! - 1-bit ordered dither (the Pico's SSD1306 with its `ordered-dither` feature): that grey
//!   level against the 4x4 matrix, white all lit (the error diffusion, the default, is tested
//!   in `core/src/pixel/error_diffusion.rs`, the window test and the emulated Pico);
//! - RGB565 (the Pico's ST7789): the LUT's 4-bit primaries scaled to 5/6/5 bits, rounded.
//!
//! And each finished row reaches the display as one `fill_contiguous` over the row, never as
//! single pixels; the Pixelbuffer's fill marks never reach it.

use std::convert::Infallible;

use embedded_graphics::pixelcolor::{BinaryColor, Gray4, GrayColor, Rgb565};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use microtrace::pixel::{FrameBuffer, LutColour, LutGrey, OrderedDither, RowDisplaySink};
use microtrace::render::{Pga, Statistics, Whole, render};
use microtrace::model::SceneDescription;
use microtrace::scene::Scene;
use microtrace::model::Palette;
use microtrace::shading::DITHER_4X4;

const CAPACITY: usize = 64;

/// An in-memory display that counts how it was drawn to.
struct Canvas<C> {
    width: u32,
    height: u32,
    pixels: Vec<Option<C>>,
    single_pixels: usize,
    fills: Vec<Rectangle>,
}

impl<C: PixelColor> Canvas<C> {
    fn new(width: u16, height: u16) -> Self {
        let (width, height) = (u32::from(width), u32::from(height));
        Self { width, height, pixels: vec![None; (width * height) as usize], single_pixels: 0, fills: Vec::new() }
    }

    fn set(&mut self, point: Point, colour: C) {
        assert!(self.bounding_box().contains(point), "{point:?} outside the display");
        self.pixels[(point.y as u32 * self.width + point.x as u32) as usize] = Some(colour);
    }
}

impl<C> OriginDimensions for Canvas<C> {
    fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }
}

impl<C: PixelColor> DrawTarget for Canvas<C> {
    type Color = C;
    type Error = Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(&mut self, pixels: I) -> Result<(), Infallible> {
        for Pixel(point, colour) in pixels {
            self.single_pixels += 1;
            self.set(point, colour);
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = C>>(&mut self, area: &Rectangle, colours: I) -> Result<(), Infallible> {
        self.fills.push(*area);
        for (point, colour) in area.points().zip(colours) {
            self.set(point, colour);
        }
        Ok(())
    }
}

/// The host's image of snooker at `width` x `height` in `f32`: palette indices, and the LUT.
fn host_image(width: u16, height: u16) -> (Vec<u8>, Palette) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/snooker.mts");
    let text = std::fs::read(path).unwrap();
    let mut description: SceneDescription<CAPACITY> = microtrace::parser::parse(&text).unwrap();
    description.fit_to_size(width, height);
    let scene = Scene::<f32, CAPACITY>::prepare(&description).unwrap();
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let mut frame = FrameBuffer::new(&mut pixels, width, height).unwrap();
    render(&scene, Pga, Whole, &mut frame, &mut Statistics::default());
    (pixels, description.palette)
}

/// Renders snooker through a `RowDisplaySink` onto `target` (with `map` made from the scene's
/// own look-up table); returns the target.
fn render_onto<D, M>(width: u16, height: u16, target: D, map: M) -> D
where
    D: DrawTarget,
    M: microtrace::pixel::ColourMap<Color = D::Color>,
{
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../scenes/snooker.mts");
    let text = std::fs::read(path).unwrap();
    let mut description: SceneDescription<CAPACITY> = microtrace::parser::parse(&text).unwrap();
    description.fit_to_size(width, height);
    let scene = Scene::<f32, CAPACITY>::prepare(&description).unwrap();
    assert!(scene.optimizations.pixelbuffer, "the test wants the Pixelbuffer's fill marks in the framebuffer");
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let frame = FrameBuffer::new(&mut pixels, width, height).unwrap();
    assert_eq!(*scene.palette, description.palette);
    let mut sink = RowDisplaySink::new(frame, target, map);
    render(&scene, Pga, Whole, &mut sink, &mut Statistics::default());
    assert_eq!(sink.failed_rows, 0);
    sink.target
}

/// Each row went as one contiguous fill of the whole row, in order, and no pixel on its own.
fn rows_went_whole<C>(canvas: &Canvas<C>, width: u16, height: u16) {
    assert_eq!(canvas.single_pixels, 0, "pixels sent one by one");
    let expected: Vec<Rectangle> =
        (0..i32::from(height)).map(|y| Rectangle::new(Point::new(0, y), Size::new(u32::from(width), 1))).collect();
    assert_eq!(canvas.fills, expected);
}

fn count_differences<C: PartialEq>(canvas: &Canvas<C>, expected: impl Iterator<Item = C>) -> usize {
    canvas.pixels.iter().zip(expected).filter(|(got, want)| got.as_ref() != Some(want)).count()
}

#[test]
fn the_4_bit_grey_path_is_the_image_through_the_luma() {
    let (width, height) = (128, 64);
    let (image, palette) = host_image(width, height);
    let canvas = render_onto(width, height, Canvas::<Gray4>::new(width, height), LutGrey::new(&palette));
    rows_went_whole(&canvas, width, height);
    // Integer Rec. 601 luma of the 4-bit entry, rounded.
    let luma = |index: u8| {
        let entry = palette.entry(index);
        let weighted = 299 * u32::from(entry.r) + 587 * u32::from(entry.g) + 114 * u32::from(entry.b);
        Gray4::new(((weighted + 500) / 1000) as u8)
    };
    assert_eq!(count_differences(&canvas, image.iter().map(|index| luma(*index))), 0);
    // Snooker is not one grey: the check compares something.
    let levels: std::collections::BTreeSet<u8> = canvas.pixels.iter().flatten().map(|grey| grey.luma()).collect();
    assert!(levels.len() >= 6, "grey levels {levels:?}");
}

#[test]
fn the_1_bit_path_is_the_grey_image_ordered_dithered() {
    let (width, height) = (128, 64);
    let (image, palette) = host_image(width, height);
    let canvas = render_onto(width, height, OrderedDither(Canvas::<BinaryColor>::new(width, height)), LutGrey::new(&palette)).0;
    rows_went_whole(&canvas, width, height);
    let expected = image.iter().enumerate().map(|(offset, index)| {
        let (x, y) = (offset % usize::from(width), offset / usize::from(width));
        let level = palette.entry(*index).luminance();
        BinaryColor::from(level == 15 || DITHER_4X4[x % 4][y % 4] < level)
    });
    assert_eq!(count_differences(&canvas, expected), 0);
    let lit = canvas.pixels.iter().flatten().filter(|colour| colour.is_on()).count();
    assert!(lit > 0 && lit < canvas.pixels.len(), "{lit} dots lit");
}

#[test]
fn the_rgb565_path_is_the_image_through_the_look_up_table() {
    let (width, height) = (240, 240);
    let (image, palette) = host_image(width, height);
    let canvas = render_onto(width, height, Canvas::<Rgb565>::new(width, height), LutColour::<Rgb565>::new(&palette));
    rows_went_whole(&canvas, width, height);
    let scale = |level: u8, max: u32| ((u32::from(level) * max + 7) / 15) as u8;
    let expected = image.iter().map(|index| {
        let entry = palette.entry(*index);
        Rgb565::new(scale(entry.r, 31), scale(entry.g, 63), scale(entry.b, 31))
    });
    assert_eq!(count_differences(&canvas, expected), 0);
    let colours: std::collections::BTreeSet<u16> =
        canvas.pixels.iter().flatten().map(|colour| embedded_graphics::pixelcolor::raw::RawU16::from(*colour).into_inner()).collect();
    assert!(colours.len() >= 16, "{} colours", colours.len());
}
