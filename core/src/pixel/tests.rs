use super::*;
use crate::shading::{Palette, Rgb4};

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

    let mut colour = DrawTargetSink { target: MockDisplay::<EgRgb888>::new(), palette: &palette, offset: Point::new(1, 2) };
    colour.write_row(0, 0, &[17, 18]);
    assert_eq!(colour.target.get_pixel(Point::new(1, 2)), Some(EgRgb888::RED));
    assert_eq!(colour.target.get_pixel(Point::new(2, 2)), Some(EgRgb888::GREEN));

    let mut grey = GreyDrawTargetSink { target: MockDisplay::<Gray4>::new(), palette: &palette, offset: Point::zero() };
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
    let mut filled = DrawTargetSink { target: MockDisplay::<EgRgb888>::new(), palette: &palette, offset: Point::new(1, 2) };
    let mut pixel_by_pixel = DrawTargetSink { target: MockDisplay::<EgRgb888>::new(), palette: &palette, offset: Point::new(1, 2) };
    filled.fill_row(2, 3, 5, 17);
    (2..7).for_each(|x| pixel_by_pixel.set_pixel(x, 3, 17));
    filled.target.assert_eq(&pixel_by_pixel.target);

    let mut filled = GreyDrawTargetSink { target: MockDisplay::<Gray4>::new(), palette: &palette, offset: Point::zero() };
    let mut pixel_by_pixel = GreyDrawTargetSink { target: MockDisplay::<Gray4>::new(), palette: &palette, offset: Point::zero() };
    filled.fill_row(0, 1, 4, 17);
    (0..4).for_each(|x| pixel_by_pixel.set_pixel(x, 1, 17));
    filled.target.assert_eq(&pixel_by_pixel.target);
}
