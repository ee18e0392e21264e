//! The overlay on the image of what the optimizations see (thesis figures 4.14a, 4.15a): each
//! object's screen extent as the core's Extents optimization computed it, and the Grid's cells
//! (`Scene::acceleration`). The plan view and the depth ranges are drawn beside it ([`super::plan`],
//! [`super::depth_ranges`]).

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;

use super::colours::object_colour;

/// One object's screen extent: first and last column, first and last row.
#[derive(Clone, Copy, Debug)]
pub struct ScreenExtent {
    /// The object's number in the scene (from 0), for its colour.
    pub object: usize,
    pub columns: (u16, u16),
    pub rows: (u16, u16),
}

pub fn draw(extents: &[ScreenExtent], target: &mut SimulatorDisplay<Rgb888>) {
    for extent in extents {
        if extent.columns.0 > extent.columns.1 || extent.rows.0 > extent.rows.1 {
            continue;
        }
        let top_left = Point::new(i32::from(extent.columns.0), i32::from(extent.rows.0));
        let size = Size::new(u32::from(extent.columns.1 - extent.columns.0) + 1, u32::from(extent.rows.1 - extent.rows.0) + 1);
        let _ = Rectangle::new(top_left, size).into_styled(PrimitiveStyle::with_stroke(object_colour(extent.object), 1)).draw(target);
    }
}

/// The Grid's cell boundaries in image pixels.
#[derive(Clone, Debug, Default)]
pub struct GridLines {
    pub columns: Vec<u16>,
    pub rows: Vec<u16>,
    pub width: u16,
    pub height: u16,
}

/// Draws the cell boundaries as dotted grey lines.
pub fn draw_grid(grid: &GridLines, target: &mut SimulatorDisplay<Rgb888>) {
    let colour = Rgb888::new(160, 160, 160);
    let vertical = grid.columns.iter().flat_map(|&x| (0..grid.height).step_by(2).map(move |y| (x, y)));
    let horizontal = grid.rows.iter().flat_map(|&y| (0..grid.width).step_by(2).map(move |x| (x, y)));
    let pixels = vertical.chain(horizontal).map(|(x, y)| Pixel(Point::new(i32::from(x), i32::from(y)), colour));
    let _ = target.draw_iter(pixels);
}
