//! The side panel: settings, statistics and render time, key help.

use embedded_graphics::mono_font::ascii::FONT_6X10;
use embedded_graphics::mono_font::MonoTextStyle;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Baseline, Text};
use embedded_graphics_simulator::SimulatorDisplay;

use super::keys::HELP;

pub const WIDTH: u32 = 264;
pub const LINE: i32 = 11;

/// Draws `lines` and then the key help from `origin` down.
pub fn draw(lines: &[String], target: &mut SimulatorDisplay<Rgb888>, origin: Point) {
    let text = MonoTextStyle::new(&FONT_6X10, Rgb888::new(230, 230, 230));
    let help = MonoTextStyle::new(&FONT_6X10, Rgb888::new(150, 200, 255));
    let mut y = origin.y;
    for line in lines {
        let _ = Text::with_baseline(line, Point::new(origin.x, y), text, Baseline::Top).draw(target);
        y += LINE;
    }
    y += LINE / 2;
    for (key, what) in HELP {
        let _ = Text::with_baseline(&format!("{key:>5} {what}"), Point::new(origin.x, y), help, Baseline::Top).draw(target);
        y += LINE;
    }
}

/// The panel's height for `lines` lines of text.
pub fn height(lines: usize) -> u32 {
    ((lines + HELP.len() + 1) as i32 * LINE) as u32
}
