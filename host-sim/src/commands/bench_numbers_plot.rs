//! The plot of `bench --numbers`, five panels in one PNG:
//! - on top, the host: speed (render time relative to f64) against error (% of pixels whose
//!   palette index differs from f64's, log scale), one point per number type per scene group;
//! - below, two by two, one panel per Cortex-M board (Cortex-M0 microbit, Cortex-M3
//!   lm3s6965evb, Cortex-M4F mps2-an386, Cortex-M33 mps2-an505):
//!   instructions per 128x64 frame (log scale, from the firmware report) against the same error
//!   at 128x64, one point per number type per thesis scene, so that a number type for a board
//!   is picked from one picture.
//!
//! Drawn in memory with plotters and written as a PNG; text uses the DejaVu Sans font in
//! host-sim/assets/ (no system fonts needed).

use std::path::Path;

use anyhow::Context;
use plotters::coord::combinators::BindKeyPoints;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;

use crate::files;

/// One point of the host panel: a number type in one scene group.
#[derive(Clone, Debug)]
pub struct PlotPoint {
    pub number: &'static str,
    pub group: &'static str,
    pub time_relative_to_f64: f64,
    pub percent_differing: f64,
}

/// One point of a board panel: a number type on one thesis scene at 128x64, on one board.
#[derive(Clone, Debug)]
pub struct BoardPoint {
    pub board: &'static str,
    /// The scene's file stem (`snooker`).
    pub scene: String,
    pub number: &'static str,
    /// The firmware's instructions for the frame: preparation plus render.
    pub instructions_per_frame: u64,
    /// False when the report had no `frame_instructions` and `instructions_per_frame` is its
    /// `instructions`, the render's alone (reports from before the frame was measured).
    pub whole_frame: bool,
    /// The host's render in this type against f64's, at the same 128x64.
    pub percent_differing: f64,
}

/// A board panel: its title and the board its points are from.
#[derive(Clone, Copy, Debug)]
pub struct BoardPanel {
    pub title: &'static str,
    pub board: &'static str,
}

pub const WIDTH: u32 = 1000;
/// The host panel's height; the board panels, side by side, are below it.
const HOST_HEIGHT: u32 = 640;
/// A row of board panels: two side by side.
const BOARD_HEIGHT: u32 = 520;
const BOARDS_PER_ROW: usize = 2;
/// Two rows of board panels: the four cores.
const BOARD_ROWS: u32 = 2;
pub const HEIGHT: u32 = HOST_HEIGHT + BOARD_ROWS * BOARD_HEIGHT;
/// A log axis cannot show 0 %: identical images are drawn on this floor line, one pixel in a
/// million, below one pixel of any image up to 1000x1000.
pub const PERCENT_FLOOR: f64 = 0.0001;
const FONT: &str = "sans-serif";
static FONT_BYTES: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");

fn number_colour(number: &str) -> RGBColor {
    match number {
        "f64" => RGBColor(0, 0, 0),
        "f32" => RGBColor(31, 119, 180),
        "fixed" => RGBColor(214, 39, 40),
        "fixed16" => RGBColor(255, 127, 14),
        "soft32" => RGBColor(148, 103, 189),
        _ => RGBColor(44, 160, 44),
    }
}

/// The marker of the `position`-th group or scene: circle, triangle, cross.
fn marker<DB: DrawingBackend>(position: usize, at: (f64, f64), colour: RGBColor) -> DynElement<'static, DB, (f64, f64)> {
    match position % 3 {
        0 => Circle::new(at, 6, colour.filled()).into_dyn(),
        1 => TriangleMarker::new(at, 8, colour.filled()).into_dyn(),
        _ => Cross::new(at, 7, colour.stroke_width(3)).into_dyn(),
    }
}

fn legend_marker<DB: DrawingBackend>(position: usize, (x, y): (i32, i32)) -> DynElement<'static, DB, (i32, i32)> {
    match position % 3 {
        0 => Circle::new((x, y), 5, BLACK.filled()).into_dyn(),
        1 => TriangleMarker::new((x, y), 7, BLACK.filled()).into_dyn(),
        _ => Cross::new((x, y), 6, BLACK.stroke_width(3)).into_dyn(),
    }
}

pub fn write(
    path: &Path,
    points: &[PlotPoint],
    groups: &[&'static str],
    board_points: &[BoardPoint],
    panels: &[BoardPanel],
) -> anyhow::Result<()> {
    plotters::style::register_font(FONT, FontStyle::Normal, FONT_BYTES)
        .map_err(|_| anyhow::anyhow!("the plot font host-sim/assets/DejaVuSans.ttf is not a usable font"))?;
    let mut buffer = vec![255u8; (WIDTH * HEIGHT * 3) as usize];
    draw(&mut buffer, points, groups, board_points, panels).map_err(|error| anyhow::anyhow!("drawing the plot: {error}"))?;
    let rgb: Vec<[u8; 3]> = buffer.chunks_exact(3).map(|pixel| [pixel[0], pixel[1], pixel[2]]).collect();
    if let Some(directory) = path.parent().filter(|directory| !directory.as_os_str().is_empty()) {
        std::fs::create_dir_all(directory).with_context(|| format!("cannot create {}", directory.display()))?;
    }
    files::write_png_rgb(path, WIDTH as u16, HEIGHT as u16, &rgb).with_context(|| format!("cannot write {}", path.display()))
}

type Area<'a> = DrawingArea<BitMapBackend<'a>, Shift>;

fn draw(
    buffer: &mut [u8],
    points: &[PlotPoint],
    groups: &[&'static str],
    board_points: &[BoardPoint],
    panels: &[BoardPanel],
) -> Result<(), Box<dyn std::error::Error>> {
    let root = BitMapBackend::with_buffer(buffer, (WIDTH, HEIGHT)).into_drawing_area();
    root.fill(&WHITE)?;
    let (host, boards) = root.split_vertically(HOST_HEIGHT);
    draw_host(&host, points, groups)?;
    // The board panels share the host panel's error axis (widened to their points), so that
    // points compare across the panels.
    let largest_percent = board_points
        .iter()
        .map(|p| p.percent_differing)
        .chain(points.iter().map(|p| p.percent_differing))
        .fold(PERCENT_FLOOR * 10.0, f64::max);
    let columns = boards.split_evenly((BOARD_ROWS as usize, BOARDS_PER_ROW));
    for (area, panel) in columns.iter().zip(panels) {
        let in_panel: Vec<&BoardPoint> = board_points.iter().filter(|p| p.board == panel.board).collect();
        draw_board(area, panel, &in_panel, largest_percent)?;
    }
    root.present()?;
    Ok(())
}

fn draw_host(area: &Area, points: &[PlotPoint], groups: &[&'static str]) -> Result<(), Box<dyn std::error::Error>> {
    let largest_time = points.iter().map(|p| p.time_relative_to_f64).fold(1.0, f64::max);
    let largest_percent = points.iter().map(|p| p.percent_differing).fold(PERCENT_FLOOR * 10.0, f64::max);
    let mut chart = ChartBuilder::on(area)
        .caption("MicroTrace number types: speed against error (host, against f64)", (FONT, 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(72)
        .build_cartesian_2d(0.0..largest_time * 1.15, (PERCENT_FLOOR * 0.5..largest_percent * 3.0).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("render time relative to f64 (median, same run)")
        .y_desc("% pixels differing from f64 (log)")
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 15))
        .y_label_formatter(&|value| percent_label(*value))
        .draw()?;
    for (position, group) in groups.iter().enumerate() {
        // f64 is the reference, at (1, 0) in every group: drawn once, below.
        let in_group = points.iter().filter(|p| p.group == *group && p.number != "f64");
        let at = |p: &PlotPoint| (p.time_relative_to_f64, p.percent_differing.max(PERCENT_FLOOR));
        let series = chart.draw_series(in_group.clone().map(|p| marker(position, at(p), number_colour(p.number))))?;
        series.label(*group).legend(move |point| legend_marker(position, point));
        // The name beside the marker, offset in pixels so it does not cover it, and lower for
        // each group so that names of points at the same place stay apart.
        let label_offset = (9, -16 + 14 * position as i32);
        chart.draw_series(in_group.map(|p| {
            EmptyElement::at(at(p)) + Text::new(p.number, label_offset, (FONT, 13).into_font().color(&number_colour(p.number)))
        }))?;
    }
    chart.draw_series([EmptyElement::at((1.0, PERCENT_FLOOR))
        + Circle::new((0, 0), 4, BLACK.filled())
        + Text::new("f64 (reference)", (-40, 8), (FONT, 13).into_font())])?;
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .label_font((FONT, 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// One board: x is the firmware's instructions per frame (log), y the error of the type's
/// render at 128x64 (f64 itself on the floor line); one marker shape per scene.
fn draw_board(area: &Area, panel: &BoardPanel, points: &[&BoardPoint], largest_percent: f64) -> Result<(), Box<dyn std::error::Error>> {
    let caption = (panel.title, (FONT, 17));
    if points.is_empty() {
        let chart = ChartBuilder::on(area).caption(caption.0, caption.1).margin(12).build_cartesian_2d(0.0..1.0, 0.0..1.0)?;
        chart.plotting_area().draw(&Text::new(
            "no instruction counts for this board in the firmware report",
            (0.05, 0.5),
            (FONT, 14).into_font(),
        ))?;
        return Ok(());
    }
    let fewest = points.iter().map(|p| p.instructions_per_frame).min().unwrap_or(1).max(1) as f64;
    let most = points.iter().map(|p| p.instructions_per_frame).max().unwrap_or(1).max(1) as f64;
    let mut chart = ChartBuilder::on(area)
        .caption(caption.0, caption.1)
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(72)
        .build_cartesian_2d(
            (fewest / 1.5..most * 1.6).log_scale().with_key_points(one_two_five(fewest / 1.5, most * 1.6)),
            (PERCENT_FLOOR * 0.5..largest_percent * 3.0).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc(if points.iter().all(|p| p.whole_frame) {
            "instructions per 128x64 frame (prepare + render, log)"
        } else if points.iter().all(|p| !p.whole_frame) {
            "instructions per 128x64 render (an older report: render only, log)"
        } else {
            "instructions per 128x64 frame, or render only where the report has no frame count (log)"
        })
        .y_desc("% pixels differing from f64 (log)")
        .label_style((FONT, 12))
        .axis_desc_style((FONT, 13))
        .x_label_formatter(&|value| millions(*value))
        .y_label_formatter(&|value| percent_label(*value))
        .draw()?;
    let mut scenes: Vec<&str> = Vec::new();
    for point in points {
        if !scenes.contains(&point.scene.as_str()) {
            scenes.push(&point.scene);
        }
    }
    for (position, scene) in scenes.iter().enumerate() {
        let in_scene = points.iter().copied().filter(|p| p.scene == *scene);
        let at = |p: &BoardPoint| (p.instructions_per_frame as f64, p.percent_differing.max(PERCENT_FLOOR));
        let series = chart.draw_series(in_scene.clone().map(|p| marker(position, at(p), number_colour(p.number))))?;
        series.label(format!("{scene} 128x64")).legend(move |point| legend_marker(position, point));
        let label_offset = (8, -15 + 13 * position as i32);
        chart.draw_series(in_scene.map(|p| {
            EmptyElement::at(at(p)) + Text::new(p.number, label_offset, (FONT, 12).into_font().color(&number_colour(p.number)))
        }))?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .label_font((FONT, 12))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// 1, 2 and 5 times the powers of ten from `low` to `high`: the instruction axis's ticks (the
/// ends, when fewer than two of those are in the range).
fn one_two_five(low: f64, high: f64) -> Vec<f64> {
    let mut ticks = Vec::new();
    let mut decade = 10f64.powf(low.max(1.0).log10().floor());
    while decade <= high {
        for step in [1.0, 2.0, 5.0] {
            let tick = decade * step;
            if (low..=high).contains(&tick) {
                ticks.push(tick);
            }
        }
        decade *= 10.0;
    }
    if ticks.len() < 2 {
        // A narrow range: its ends.
        ticks = vec![low, high];
    }
    ticks
}

fn percent_label(value: f64) -> String {
    if value <= PERCENT_FLOOR * 1.0001 {
        return "0 (identical)".into();
    }
    // Two significant digits at most, without the binary fraction's tail (0.0009000000000001).
    let decimals = ((-value.log10()).ceil().max(0.0) as usize) + 1;
    let text = format!("{value:.decimals$}");
    let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.') } else { &text };
    text.to_owned()
}

/// 35882729 -> "35.9M", 120000000 -> "120M".
fn millions(value: f64) -> String {
    let millions = value / 1e6;
    if millions >= 100.0 {
        format!("{millions:.0}M")
    } else if millions >= 10.0 {
        format!("{}M", (millions * 10.0).round() / 10.0)
    } else {
        format!("{}M", (millions * 100.0).round() / 100.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_labels_are_short() {
        assert_eq!(percent_label(PERCENT_FLOOR), "0 (identical)");
        assert_eq!(percent_label(0.0009000000000001), "0.0009");
        assert_eq!(percent_label(0.25), "0.25");
        assert_eq!(percent_label(10.0), "10");
        assert_eq!(percent_label(1.0), "1");
        assert_eq!(millions(35_882_729.0), "35.9M");
        assert_eq!(millions(163_180_021.0), "163M");
        assert_eq!(millions(2_000_000.0), "2M");
        assert_eq!(one_two_five(8.7e6, 2.7e8), [1e7, 2e7, 5e7, 1e8, 2e8]);
        assert_eq!(one_two_five(1.5e7, 1.9e7), [1.5e7, 1.9e7]);
    }
}
