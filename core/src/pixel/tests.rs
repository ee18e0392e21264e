use super::*;
use crate::model::{Palette, Rgb4};

#[test]
fn frame_buffer_writes_reads_and_ignores_outside_pixels() {
    let mut pixels = [0u8; 6];
    let mut frame = FrameBuffer::new(&mut pixels, 3, 2).unwrap();
    frame.set_pixel(2, 1, 9);
    frame.set_pixel(3, 0, 7); // outside: ignored
    frame.write_row(1, 0, &[4, 5, 6]); // the 6 falls off the right edge
    let mut row = [0u8; 3];
    frame.read_row(0, 0, &mut row);
    assert_eq!(row, [0, 4, 5]);
    assert_eq!(frame.get_pixel(2, 1), Some(9));
    assert_eq!(frame.get_pixel(0, 2), None);
    assert_eq!(pixels, [0, 4, 5, 0, 0, 9]);
    assert!(FrameBuffer::new(&mut [0u8; 5], 3, 2).is_none());
}

#[test]
fn mock_sink_counts_writes_and_rows() {
    let mut mock = MockSink::<u8, 2, 2>::new(1);
    mock.fill_row(0, 1, 3, 8);
    mock.row_done(1);
    assert_eq!(mock.pixels, [[1, 1], [8, 8]]);
    assert_eq!((mock.writes, mock.out_of_bounds, mock.rows_done), (3, 1, 1));
}

#[cfg(feature = "embedded-graphics")]
#[test]
fn draw_target_adapters_go_through_the_look_up_table() {
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::{Gray4, GrayColor, Rgb888 as EgRgb888, RgbColor};
    use embedded_graphics::prelude::*;

    let mut palette = Palette::grey();
    palette.entries[17] = Rgb4::new(15, 0, 0);
    palette.entries[18] = Rgb4::new(0, 15, 0);

    let mut colour = DrawTargetSink { target: MockDisplay::<EgRgb888>::new(), colours: crate::pixel::LutColour::new(&palette), offset: Point::new(1, 2) };
    colour.write_row(0, 0, &[17, 18]);
    assert_eq!(colour.target.get_pixel(Point::new(1, 2)), Some(EgRgb888::RED));
    assert_eq!(colour.target.get_pixel(Point::new(2, 2)), Some(EgRgb888::GREEN));

    let mut grey = GreyDrawTargetSink { target: MockDisplay::<Gray4>::new(), colours: crate::pixel::LutGrey::new(&palette), offset: Point::zero() };
    grey.set_pixel(0, 0, 15); // grey ramp shade 15: white
    grey.set_pixel(1, 0, 17); // pure red: luma 0.299 · 15 = 4.5 -> 4
    grey.set_pixel(2, 0, 18); // pure green: 0.587 · 15 = 8.8 -> 9
    assert_eq!(grey.target.get_pixel(Point::new(0, 0)).map(|c| c.luma()), Some(15));
    assert_eq!(grey.target.get_pixel(Point::new(1, 0)).map(|c| c.luma()), Some(4));
    assert_eq!(grey.target.get_pixel(Point::new(2, 0)).map(|c| c.luma()), Some(9));
    let _ = Gray4::WHITE;
}

/// The fast `fill_row` paths write exactly what the default (one `set_pixel` per pixel) does,
/// clipped at the right edge.
#[test]
fn fill_row_fast_paths_match_the_default() {
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::{Gray4, Rgb888 as EgRgb888};
    use embedded_graphics::prelude::*;

    let mut pixels = [0u8; 8];
    let mut frame = FrameBuffer::new(&mut pixels, 4, 2).unwrap();
    frame.fill_row(1, 1, 10, 7); // runs past the right edge
    frame.fill_row(4, 0, 2, 9); // starts outside: nothing
    assert_eq!(frame.pixels(), &[0, 0, 0, 0, 0, 7, 7, 7]);

    let mut palette = Palette::grey();
    palette.entries[17] = Rgb4::new(15, 0, 0);
    let mut filled = DrawTargetSink { target: MockDisplay::<EgRgb888>::new(), colours: crate::pixel::LutColour::new(&palette), offset: Point::new(1, 2) };
    let mut pixel_by_pixel = DrawTargetSink { target: MockDisplay::<EgRgb888>::new(), colours: crate::pixel::LutColour::new(&palette), offset: Point::new(1, 2) };
    filled.fill_row(2, 3, 5, 17);
    (2..7).for_each(|x| pixel_by_pixel.set_pixel(x, 3, 17));
    filled.target.assert_eq(&pixel_by_pixel.target);

    let mut filled = GreyDrawTargetSink { target: MockDisplay::<Gray4>::new(), colours: crate::pixel::LutGrey::new(&palette), offset: Point::zero() };
    let mut pixel_by_pixel = GreyDrawTargetSink { target: MockDisplay::<Gray4>::new(), colours: crate::pixel::LutGrey::new(&palette), offset: Point::zero() };
    filled.fill_row(0, 1, 4, 17);
    (0..4).for_each(|x| pixel_by_pixel.set_pixel(x, 1, 17));
    filled.target.assert_eq(&pixel_by_pixel.target);
}

/// The 1-bit ordered dither: in every aligned 4x4 block grey level L lights L dots for L < 15
/// and full white all 16; each level's dots include the level below's.
#[cfg(feature = "embedded-graphics")]
#[test]
fn ordered_dither_lights_level_dots_and_white_lights_all() {
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::{BinaryColor, Gray4};
    use embedded_graphics::prelude::*;
    use embedded_graphics::primitives::Rectangle;

    let mut previous: Option<MockDisplay<BinaryColor>> = None;
    for level in 0..16u8 {
        let mut dither = OrderedDither(MockDisplay::<BinaryColor>::new());
        // An 8x8 area at (4, 8): four aligned blocks.
        dither.fill_solid(&Rectangle::new(Point::new(4, 8), Size::new(8, 8)), Gray4::new(level)).unwrap();
        let lit = dither.0.affected_area().points().filter(|point| dither.0.get_pixel(*point) == Some(BinaryColor::On)).count();
        let expected = if level == 15 { 16 } else { usize::from(level) };
        assert_eq!(lit, 4 * expected, "level {level}");
        if let Some(previous) = &previous {
            for point in Rectangle::new(Point::new(4, 8), Size::new(8, 8)).points() {
                if previous.get_pixel(point) == Some(BinaryColor::On) {
                    assert_eq!(dither.0.get_pixel(point), Some(BinaryColor::On), "level {level} at {point:?}");
                }
            }
        }
        previous = Some(dither.0);
    }
}

/// The dither's patterns, from the core's DITHER_4X4 (`[x % 4][y % 4]`), on a 4x4 block.
#[cfg(feature = "embedded-graphics")]
#[test]
fn ordered_dither_patterns() {
    use embedded_graphics::mock_display::MockDisplay;
    use embedded_graphics::pixelcolor::{BinaryColor, Gray4};
    use embedded_graphics::prelude::*;
    use embedded_graphics::primitives::Rectangle;

    let block = Rectangle::new(Point::zero(), Size::new(4, 4));
    let pattern = |level: u8| {
        let mut dither = OrderedDither(MockDisplay::<BinaryColor>::new());
        dither.fill_solid(&block, Gray4::new(level)).unwrap();
        dither.0
    };
    pattern(0).assert_pattern(&["....", "....", "....", "...."]);
    pattern(1).assert_pattern(&["#...", "....", "....", "...."]);
    pattern(8).assert_pattern(&["#.#.", ".#.#", "#.#.", ".#.#"]);
    pattern(14).assert_pattern(&["###.", "####", "#.##", "####"]);
    pattern(15).assert_pattern(&["####", "####", "####", "####"]);

    // draw_iter, fill_contiguous and fill_solid dither alike.
    let mut by_pixel = OrderedDither(MockDisplay::<BinaryColor>::new());
    by_pixel.draw_iter(block.points().map(|point| Pixel(point, Gray4::new(8)))).unwrap();
    by_pixel.0.assert_eq(&pattern(8));
    let mut contiguous = OrderedDither(MockDisplay::<BinaryColor>::new());
    contiguous.fill_contiguous(&block, core::iter::repeat(Gray4::new(8))).unwrap();
    contiguous.0.assert_eq(&pattern(8));
    for level in 1..15u8 {
        let mut contiguous = OrderedDither(MockDisplay::<BinaryColor>::new());
        contiguous.fill_contiguous(&block, core::iter::repeat(Gray4::new(level))).unwrap();
        contiguous.0.assert_eq(&pattern(level));
    }
}

/// A `DrawTarget` that records what it was asked to do, for the row sink's test.
#[cfg(feature = "embedded-graphics")]
mod recorder {
    extern crate std;
    use embedded_graphics::pixelcolor::Gray4;
    use embedded_graphics::prelude::*;
    use embedded_graphics::primitives::Rectangle;
    use std::vec::Vec;

    #[derive(Default)]
    pub struct Recorder {
        pub pixels_drawn: usize,
        pub fills: Vec<(Rectangle, Vec<Gray4>)>,
    }

    impl OriginDimensions for Recorder {
        fn size(&self) -> Size {
            Size::new(16, 16)
        }
    }

    impl DrawTarget for Recorder {
        type Color = Gray4;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Gray4>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
            self.pixels_drawn += pixels.into_iter().count();
            Ok(())
        }
        fn fill_contiguous<I: IntoIterator<Item = Gray4>>(&mut self, area: &Rectangle, colours: I) -> Result<(), Self::Error> {
            self.fills.push((*area, colours.into_iter().collect()));
            Ok(())
        }
    }
}

/// RowDisplaySink: nothing reaches the display before a row is finished; then the row goes as
/// one `fill_contiguous` over its rectangle, through the colour map, and no pixel on its own.
#[cfg(feature = "embedded-graphics")]
#[test]
fn row_display_sink_sends_each_finished_row_as_one_contiguous_fill() {
    use embedded_graphics::pixelcolor::Gray4;
    use embedded_graphics::prelude::*;
    use embedded_graphics::primitives::Rectangle;

    let mut palette = Palette::grey();
    palette.entries[17] = Rgb4::new(15, 0, 0); // luma 4
    let mut pixels = [0u8; 12];
    let frame = FrameBuffer::new(&mut pixels, 4, 3).unwrap();
    let mut sink = RowDisplaySink::new(frame, recorder::Recorder::default(), LutGrey::new(&palette));
    sink.offset = Point::new(2, 5);
    sink.fill_row(0, 1, 4, 3);
    sink.set_pixel(2, 1, 17);
    sink.fill_row(0, 2, 4, 9); // a row written but not finished: never sent
    assert!(sink.target.fills.is_empty());
    assert_eq!(sink.get_pixel(2, 1), Some(17), "the framebuffer is the sink's source");
    sink.row_done(1);
    assert_eq!(sink.target.pixels_drawn, 0);
    assert_eq!(sink.target.fills.len(), 1);
    let (area, colours) = &sink.target.fills[0];
    assert_eq!(*area, Rectangle::new(Point::new(2, 6), Size::new(4, 1)));
    assert_eq!(colours.as_slice(), &[Gray4::new(3), Gray4::new(3), Gray4::new(4), Gray4::new(3)]);
    assert_eq!(sink.failed_rows, 0);
}

/// The colour path rounds the LUT's 4-bit primaries to RGB565's 5/6/5 bits.
#[cfg(feature = "embedded-graphics")]
#[test]
fn lut_colour_to_rgb565() {
    use embedded_graphics::pixelcolor::Rgb565;
    use embedded_graphics::prelude::*;

    let mut palette = Palette::grey();
    palette.entries[1] = Rgb4::new(15, 8, 1);
    let map = LutColour::<Rgb565>::new(&palette);
    assert_eq!(map.colour(15), Rgb565::WHITE);
    assert_eq!(map.colour(0), Rgb565::BLACK);
    // 15 -> 31; 8 -> round(8 * 63 / 15) = 34; 1 -> round(31 / 15) = 2.
    assert_eq!(map.colour(1), Rgb565::new(31, 34, 2));
}
