//! Sortlist's depth ranges (§4.7.5, the thesis's znear and zfar, figures 4.10 and 4.14b): one
//! bar per object from the near bound of the ray parameter `t` (what Sortlist sorts by and
//! stops at) to the far bound, in Sortlist's test order, in the object's colour. Where bars
//! overlap little, Sortlist ends the loop early.

use embedded_graphics::mono_font::ascii::{FONT_4X6, FONT_6X10};
use embedded_graphics::mono_font::MonoTextStyle;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use embedded_graphics::text::{Alignment, Baseline, Text, TextStyleBuilder};
use embedded_graphics_simulator::SimulatorDisplay;

use super::colours::object_colour;
use super::plan::PlanView;

/// Height of the title and of the axis labels.
const TEXT: u32 = 12;
/// Height given to the bars of a scene with many objects.
const BARS: u32 = 160;
/// Width of the object numbers left of the bars.
const LABELS: i32 = 14;

/// Vertical distance between bars: up to 8 pixels, at least 3.
fn pitch(objects: usize) -> u32 {
    (BARS / objects.max(1) as u32).clamp(3, 8)
}

/// The height the chart takes for `objects` objects.
pub fn height(objects: usize) -> u32 {
    2 * TEXT + pitch(objects) * objects as u32
}

/// Draws the chart with its top left at `origin`, `width` wide.
pub fn draw(plan: &PlanView, target: &mut SimulatorDisplay<Rgb888>, origin: Point, width: u32) {
    let text = MonoTextStyle::new(&FONT_6X10, Rgb888::new(230, 230, 230));
    let _ = Text::with_baseline("Sortlist t near..far (test order)", origin, text, Baseline::Top).draw(target);
    let ranges: Vec<(usize, f64, f64)> = plan
        .order
        .iter()
        .filter_map(|&object| plan.objects.get(object))
        .filter_map(|object| object.depth.map(|(near, far)| (object.object, near, far)))
        .collect();
    if ranges.is_empty() {
        let _ = Text::with_baseline("no depth bounds", origin + Point::new(0, TEXT as i32), text, Baseline::Top).draw(target);
        return;
    }
    let low = ranges.iter().map(|range| range.1).fold(f64::INFINITY, f64::min);
    let high = ranges.iter().map(|range| range.2).fold(f64::NEG_INFINITY, f64::max);
    let span = (high - low).max(1e-9);
    let left = origin.x + LABELS + 2;
    let length = f64::from(width as i32 - LABELS - 4);
    let x = |t: f64| left + ((t - low) / span * length).round() as i32;
    let pitch = pitch(plan.objects.len());
    let label = MonoTextStyle::new(&FONT_4X6, Rgb888::new(170, 170, 170));
    let right_aligned = TextStyleBuilder::new().alignment(Alignment::Right).baseline(Baseline::Top).build();
    let mut y = origin.y + TEXT as i32;
    for (object, near, far) in ranges {
        let colour = object_colour(object);
        let bar = Rectangle::with_corners(Point::new(x(near), y), Point::new(x(far), y + pitch as i32 - 2));
        let _ = bar.into_styled(PrimitiveStyle::with_fill(colour)).draw(target);
        if pitch >= 7 {
            // Numbered from 1 in the scene file's order.
            let number = format!("{}", object + 1);
            let _ = Text::with_text_style(&number, Point::new(origin.x + LABELS, y), label, right_aligned).draw(target);
        }
        y += pitch as i32;
    }
    let axis = MonoTextStyle::new(&FONT_6X10, Rgb888::new(150, 150, 150));
    let _ = Text::with_baseline(&format!("t={low:.0}"), Point::new(left, y + 1), axis, Baseline::Top).draw(target);
    let end = Point::new(left + length as i32, y + 1);
    let _ = Text::with_text_style(&format!("{high:.0}"), end, axis, TextStyleBuilder::new().alignment(Alignment::Right).baseline(Baseline::Top).build()).draw(target);
}

#[cfg(test)]
mod tests {
    use embedded_graphics::pixelcolor::Rgb888;
    use embedded_graphics::prelude::*;
    use embedded_graphics_simulator::SimulatorDisplay;

    use super::super::colours::object_colour;
    use super::super::plan::PlanView;
    use super::super::test_scenes::prepared;
    use super::{draw, height};

    /// One bar per object in its colour, top to bottom in Sortlist's order, left ends in order
    /// of near bound, all within the chart's height.
    #[test]
    fn one_bar_per_object_in_sortlist_order() {
        for name in ["snooker", "lattice"] {
            let (_, scene) = prepared(name);
            let plan = PlanView::of(&*scene);
            let size = Size::new(256, height(plan.objects.len()));
            let mut display = SimulatorDisplay::<Rgb888>::new(size + Size::new(0, 40));
            draw(&plan, &mut display, Point::zero(), size.width);
            let mut previous = (i32::MIN, i32::MIN);
            for &object in &plan.order {
                let colour = object_colour(object);
                let points: Vec<Point> = display.bounding_box().points().filter(|p| display.get_pixel(*p) == colour).collect();
                assert!(!points.is_empty(), "{name}: no bar for object {object}");
                let top = points.iter().map(|p| p.y).min().unwrap();
                let left = points.iter().map(|p| p.x).min().unwrap();
                assert!(points.iter().all(|p| p.y < size.height as i32), "{name}: bar {object} below the chart");
                assert!(top > previous.0 && left >= previous.1, "{name}: bar {object} out of order");
                previous = (top, left);
            }
        }
    }
}
