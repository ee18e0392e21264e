//! One call from a prepared scene to any embedded-graphics display: the render in the streamed
//! order (each row once, top first, nothing read back), each pixel through the display's
//! colour map — PGA mode through the scene's look-up table, or RGB mode.

use core::fmt;

use embedded_graphics_core::pixelcolor::Rgb888 as EgRgb888;
use embedded_graphics_core::prelude::DrawTarget;

use super::{render, Pga, Rgb, Statistics, Streamed};
use crate::config::Config;
use crate::number::Number;
use crate::pixel::{Borrowed, DrawTargetSink, LutColour, RgbColour};
use crate::scene::Prepared;

/// Which of the render's pixel modes reaches the display.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Colours {
    /// PGA mode: each pixel a palette index, shown as its look-up-table entry (4 bits a
    /// primary; the thesis's 256-colour display).
    Palette,
    /// RGB mode: 8 bits a primary (§4.2.4's RGB shading).
    Rgb,
}

/// The display is not the size the scene was prepared for (fit the description to the
/// display's size first: `Description::fit_to_size`, or bake at that size).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SizeMismatch {
    /// The scene's image, width and height.
    pub scene: (u16, u16),
    /// The display's drawing area, width and height.
    pub display: (u32, u32),
}

impl fmt::Display for SizeMismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (sw, sh) = self.scene;
        let (dw, dh) = self.display;
        write!(f, "the scene is {sw}x{sh} pixels but the display is {dw}x{dh}: fit the scene to the display's size (`fit_to_size({dw}, {dh})`) before preparing it")
    }
}

/// Renders `scene` onto `display` in one call: the whole image, each row drawn as it is done
/// (no framebuffer), `colours` saying which mode; returns the render's statistics. The
/// display's drawing area must be the scene's size: a scene prepared for another size is an
/// error, never a corner of the picture.
///
/// # Examples
///
/// ```
/// use embedded_graphics::mock_display::MockDisplay;
/// use embedded_graphics::pixelcolor::Rgb565;
/// use microtrace::render::{draw, Colours};
///
/// let text = b"window -2 2 -2 2\nviewplane 0\nperspective 0 0 10\nlight point 2 10 5\nsphere\n  colour 2\n";
/// let mut description: microtrace::model::SceneDescription<4> = microtrace::parser::parse(text).unwrap();
/// description.fit_to_size(64, 64);
/// let scene = microtrace::scene::Scene::<f32, 4>::prepare(&description).unwrap();
/// let mut display = MockDisplay::<Rgb565>::new();
/// let statistics = draw(&scene, Colours::Palette, &mut display).unwrap();
/// assert!(statistics.rays_traced > 0);
/// ```
pub fn draw<N, C, D>(scene: &Prepared<C>, colours: Colours, display: &mut D) -> Result<Statistics, SizeMismatch>
where
    N: Number,
    C: Config<Number = N>,
    D: DrawTarget,
    D::Color: From<EgRgb888>,
{
    let viewport = scene.viewport();
    let area = display.bounding_box();
    if area.size.width != u32::from(viewport.width()) || area.size.height != u32::from(viewport.height()) {
        return Err(SizeMismatch { scene: (viewport.width(), viewport.height()), display: (area.size.width, area.size.height) });
    }
    let mut statistics = Statistics::default();
    match colours {
        Colours::Palette => {
            let mut sink = DrawTargetSink { target: Borrowed(display), colours: LutColour::new(&scene.palette), offset: area.top_left };
            render(scene, Pga, Streamed, &mut sink, &mut statistics);
        }
        Colours::Rgb => {
            let mut sink = DrawTargetSink { target: Borrowed(display), colours: RgbColour::new(), offset: area.top_left };
            render(scene, Rgb, Streamed, &mut sink, &mut statistics);
        }
    }
    Ok(statistics)
}

impl core::error::Error for SizeMismatch {}
