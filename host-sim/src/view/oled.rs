//! The display preview: the scene as the firmware's 128x64 16-grey OLED shows it. The scene is
//! fitted with `fit_to_size(128, 64)` (what the firmware does) and rendered in PGA mode through
//! the core's `GreyDrawTargetSink` (the firmware's own index -> grey mapping).

use embedded_graphics::pixelcolor::{Gray4, GrayColor, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use microtrace::pixel::{FrameBuffer, GreyDrawTargetSink, PixelSink, PixelSource};
use microtrace::render::{render_pga, Statistics};
use microtrace::scene::Scene;

use crate::number_type::NumberType;
use crate::scene_file::{HostScene, HOST_MAX_OBJECTS};
use crate::with_number_type;

use super::sink::Borrowed;

pub const WIDTH: u16 = 128;
pub const HEIGHT: u16 = 64;
/// How much larger the preview is drawn in the window.
pub const ZOOM: u32 = 2;

/// Keeps the pixels for read-back and drives the grey display with every row.
struct OledSink<'a> {
    frame: FrameBuffer<'a, u8>,
    grey: GreyDrawTargetSink<'a, Borrowed<'a, SimulatorDisplay<Gray4>>>,
}

impl PixelSink<u8> for OledSink<'_> {
    fn set_pixel(&mut self, x: u16, y: u16, value: u8) {
        self.write_row(x, y, &[value]);
    }
    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        self.frame.write_row(x, y, values);
        self.grey.write_row(x, y, values);
    }
}

impl PixelSource<u8> for OledSink<'_> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<u8> {
        self.frame.get_pixel(x, y)
    }
}

/// Renders the OLED's view of `scene`.
pub fn render(scene: &HostScene, number: NumberType) -> anyhow::Result<SimulatorDisplay<Gray4>> {
    let mut fitted = scene.clone();
    fitted.fit_to_size(WIDTH, HEIGHT);
    let (width, height) = (fitted.viewport.width(), fitted.viewport.height());
    let mut oled = SimulatorDisplay::<Gray4>::new(Size::new(u32::from(WIDTH), u32::from(HEIGHT)));
    let mut buffer = vec![0u8; usize::from(width) * usize::from(height)];
    with_number_type!(number, N => {
        let prepared = Box::new(Scene::<N, HOST_MAX_OBJECTS>::prepare(&fitted).map_err(anyhow::Error::new)?);
        let frame = FrameBuffer::new(&mut buffer, width, height).expect("buffer sized to the viewport");
        let mut sink = OledSink { frame, grey: GreyDrawTargetSink { target: Borrowed(&mut oled), palette: &fitted.palette, offset: Point::zero() } };
        render_pga(&*prepared, &mut sink, &mut Statistics::default());
    });
    Ok(oled)
}

/// Draws the preview scaled up at `origin`, with a frame around it.
pub fn draw(oled: &SimulatorDisplay<Gray4>, target: &mut SimulatorDisplay<Rgb888>, origin: Point) {
    let zoom = ZOOM as i32;
    let pixels = (0..i32::from(HEIGHT)).flat_map(|y| (0..i32::from(WIDTH)).map(move |x| (x, y))).flat_map(|(x, y)| {
        let level = oled.get_pixel(Point::new(x, y)).luma() * 17;
        let colour = Rgb888::new(level, level, level);
        (0..zoom * zoom).map(move |i| Pixel(origin + Point::new(x * zoom + i % zoom, y * zoom + i / zoom), colour))
    });
    let _ = target.draw_iter(pixels);
    let _ = Rectangle::new(origin - Point::new(1, 1), Size::new(u32::from(WIDTH) * ZOOM + 2, u32::from(HEIGHT) * ZOOM + 2))
        .into_styled(PrimitiveStyle::with_stroke(Rgb888::new(90, 90, 90), 1))
        .draw(target);
}
