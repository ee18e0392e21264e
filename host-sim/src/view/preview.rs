//! The display preview: the scene as each kind of display the firmware drives shows it, with
//! the firmware's own mapping. The scene is fitted to the display (`fit_to_size`, as the
//! firmware and the real-board examples do), rendered in PGA mode, and each finished row sent
//! to a simulated display of the display's own colour type through the core's
//! `RowDisplaySink`:
//!
//! - the lm3s6965evb's 128x64 16-grey SSD0323 OLED: `LutGrey` (the look-up-table entry's luma,
//!   `grey_level`, as the firmware's OLED rows), into a `Gray4` display;
//! - a 128x64 1-bit SSD1306 (the Pico example): `LutLuma` (the entry's 8-bit luma) through the
//!   core's `ErrorDiffusion` (its tone curve, then Floyd–Steinberg) into a `BinaryColor`
//!   display, lit dots white; or, as the example's `ordered-dither` feature, `LutGrey` through
//!   `OrderedDither`;
//! - a 240x240 RGB565 panel (the Pico + ST7789 example): `LutColour<Rgb565>` into an `Rgb565`
//!   display, shown as embedded-graphics converts RGB565 to 8 bits a primary.

use embedded_graphics::pixelcolor::{BinaryColor, Gray4, GrayColor, Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use microtrace::pixel::{ColourMap, ErrorDiffusion, FrameBuffer, LutColour, LutGrey, LutLuma, OrderedDither, RowDisplaySink};
use microtrace::render::{Pga, Statistics, Whole};

use microtrace::number::NumberKind;
use crate::scene_file::HostScene;
use crate::heap::HostPrepared;
use microtrace::with_number_kind;

use microtrace::pixel::Borrowed;

/// The kinds of display previewed; `L` in the window cycles them in this order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum DisplayKind {
    /// The lm3s6965evb's 128x64 16-grey SSD0323 OLED.
    Oled,
    /// A 128x64 black-and-white SSD1306, grey by error diffusion (the Pico example's default).
    Ssd1306,
    /// The same SSD1306, grey by the 4x4 ordered dither (the example's `ordered-dither`).
    Ssd1306Ordered,
    /// A 240x240 RGB565 colour panel (an ST7789).
    Rgb565,
}

impl DisplayKind {
    pub const ALL: [DisplayKind; 4] = [DisplayKind::Oled, DisplayKind::Ssd1306, DisplayKind::Ssd1306Ordered, DisplayKind::Rgb565];

    pub fn next(self) -> Self {
        match self {
            DisplayKind::Oled => DisplayKind::Ssd1306,
            DisplayKind::Ssd1306 => DisplayKind::Ssd1306Ordered,
            DisplayKind::Ssd1306Ordered => DisplayKind::Rgb565,
            DisplayKind::Rgb565 => DisplayKind::Oled,
        }
    }

    /// The display's size in its pixels.
    pub fn size(self) -> (u16, u16) {
        match self {
            DisplayKind::Oled | DisplayKind::Ssd1306 | DisplayKind::Ssd1306Ordered => (128, 64),
            DisplayKind::Rgb565 => (240, 240),
        }
    }

    /// How many window pixels a display pixel is drawn as, each way.
    pub fn zoom(self) -> u32 {
        match self {
            DisplayKind::Oled | DisplayKind::Ssd1306 | DisplayKind::Ssd1306Ordered => 2,
            DisplayKind::Rgb565 => 1,
        }
    }

    /// The preview's size in the window, without its frame.
    pub fn shown_size(self) -> Size {
        let (width, height) = self.size();
        Size::new(u32::from(width) * self.zoom(), u32::from(height) * self.zoom())
    }

    /// The tallest preview's height in the window (the panel's text goes below it).
    pub fn tallest() -> u32 {
        Self::ALL.iter().map(|kind| kind.shown_size().height).max().unwrap_or(0)
    }

    pub fn label(self) -> &'static str {
        match self {
            DisplayKind::Oled => "SSD0323 OLED 128x64, 16 grey",
            DisplayKind::Ssd1306 => "SSD1306 128x64, 1-bit diffused",
            DisplayKind::Ssd1306Ordered => "SSD1306 128x64, 1-bit ordered",
            DisplayKind::Rgb565 => "RGB565 panel 240x240",
        }
    }
}

/// What a display shows: its pixels as 8-bit RGB, rows top first.
pub struct Preview {
    pub kind: DisplayKind,
    pub pixels: Vec<Rgb888>,
}

/// Renders `scene` as a display of `kind` shows it.
pub fn render(scene: &HostScene, number: NumberKind, kind: DisplayKind) -> anyhow::Result<Preview> {
    let mut fitted = scene.clone();
    let (width, height) = kind.size();
    fitted.fit_to_size(width, height);
    let palette = fitted.palette;
    let size = Size::new(u32::from(width), u32::from(height));
    let pixels = match kind {
        DisplayKind::Oled => {
            let mut display = SimulatorDisplay::<Gray4>::new(size);
            render_into(&fitted, number, Borrowed(&mut display), LutGrey::new(&palette))?;
            read_back(&display, width, height, |grey| Rgb888::new(grey.luma() * 17, grey.luma() * 17, grey.luma() * 17))
        }
        DisplayKind::Ssd1306 => {
            let mut display = SimulatorDisplay::<BinaryColor>::new(size);
            render_into(&fitted, number, ErrorDiffusion::<_, 128>::new(Borrowed(&mut display)), LutLuma::new(&palette))?;
            read_back(&display, width, height, |dot| if dot.is_on() { Rgb888::WHITE } else { Rgb888::BLACK })
        }
        DisplayKind::Ssd1306Ordered => {
            let mut display = SimulatorDisplay::<BinaryColor>::new(size);
            render_into(&fitted, number, OrderedDither(Borrowed(&mut display)), LutGrey::new(&palette))?;
            read_back(&display, width, height, |dot| if dot.is_on() { Rgb888::WHITE } else { Rgb888::BLACK })
        }
        DisplayKind::Rgb565 => {
            let mut display = SimulatorDisplay::<Rgb565>::new(size);
            render_into(&fitted, number, Borrowed(&mut display), LutColour::<Rgb565>::new(&palette))?;
            read_back(&display, width, height, Rgb888::from)
        }
    };
    Ok(Preview { kind, pixels })
}

/// The render of the fitted scene into `target` through `map`, a finished row at a time, as the
/// firmware and the real-board examples send theirs.
fn render_into<D, M>(fitted: &HostScene, number: NumberKind, target: D, map: M) -> anyhow::Result<()>
where
    D: DrawTarget,
    M: ColourMap<Color = D::Color>,
{
    let (width, height) = (fitted.viewport.width(), fitted.viewport.height());
    let mut buffer = vec![0u8; usize::from(width) * usize::from(height)];
    let frame = FrameBuffer::new(&mut buffer, width, height).expect("buffer sized to the viewport");
    let mut sink = RowDisplaySink::new(frame, target, map);
    with_number_kind!(number, N => {
        let prepared = Box::new(HostPrepared::<N>::prepare(fitted).map_err(anyhow::Error::new)?);
        microtrace::render::render(&*prepared, Pga, Whole, &mut sink, &mut Statistics::default());
    });
    Ok(())
}

fn read_back<C: PixelColor>(display: &SimulatorDisplay<C>, width: u16, height: u16, shown: impl Fn(C) -> Rgb888) -> Vec<Rgb888> {
    (0..i32::from(height)).flat_map(|y| (0..i32::from(width)).map(move |x| Point::new(x, y))).map(|point| shown(display.get_pixel(point))).collect()
}

/// Draws the preview at `origin`, each display pixel as zoom x zoom window pixels, with a frame
/// around it.
pub fn draw(preview: &Preview, target: &mut SimulatorDisplay<Rgb888>, origin: Point) {
    let zoom = preview.kind.zoom() as i32;
    let width = i32::from(preview.kind.size().0);
    let pixels = preview.pixels.iter().enumerate().flat_map(|(index, colour)| {
        let (x, y) = (index as i32 % width, index as i32 / width);
        (0..zoom * zoom).map(move |i| Pixel(origin + Point::new(x * zoom + i % zoom, y * zoom + i / zoom), *colour))
    });
    let _ = target.draw_iter(pixels);
    let shown = preview.kind.shown_size();
    let _ = Rectangle::new(origin - Point::new(1, 1), shown + Size::new(2, 2))
        .into_styled(PrimitiveStyle::with_stroke(Rgb888::new(90, 90, 90), 1))
        .draw(target);
}
