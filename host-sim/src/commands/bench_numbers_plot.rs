//! The plot of `bench --numbers`: speed (render time relative to f64) against error (% of
//! pixels whose palette index differs from f64's, log scale), one point per number type per
//! scene group. Drawn in memory with plotters and written as a PNG; text uses the DejaVu Sans
//! font in host-sim/assets/ (no system fonts needed).

use std::path::Path;

use anyhow::Context;
use plotters::prelude::*;
use plotters::style::FontStyle;

use crate::files;

/// One point: a number type in one scene group.
#[derive(Clone, Debug)]
pub struct PlotPoint {
    pub number: &'static str,
    pub group: &'static str,
    pub time_relative_to_f64: f64,
    pub percent_differing: f64,
}

const WIDTH: u32 = 1000;
const HEIGHT: u32 = 640;
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

pub fn write(path: &Path, points: &[PlotPoint], groups: &[&'static str]) -> anyhow::Result<()> {
    plotters::style::register_font(FONT, FontStyle::Normal, FONT_BYTES)
        .map_err(|_| anyhow::anyhow!("the plot font host-sim/assets/DejaVuSans.ttf is not a usable font"))?;
    let mut buffer = vec![255u8; (WIDTH * HEIGHT * 3) as usize];
    draw(&mut buffer, points, groups).map_err(|error| anyhow::anyhow!("drawing the plot: {error}"))?;
    let rgb: Vec<[u8; 3]> = buffer.chunks_exact(3).map(|pixel| [pixel[0], pixel[1], pixel[2]]).collect();
    if let Some(directory) = path.parent().filter(|directory| !directory.as_os_str().is_empty()) {
        std::fs::create_dir_all(directory).with_context(|| format!("cannot create {}", directory.display()))?;
    }
    files::write_png_rgb(path, WIDTH as u16, HEIGHT as u16, &rgb).with_context(|| format!("cannot write {}", path.display()))
}

fn draw(buffer: &mut [u8], points: &[PlotPoint], groups: &[&'static str]) -> Result<(), Box<dyn std::error::Error>> {
    let root = BitMapBackend::with_buffer(buffer, (WIDTH, HEIGHT)).into_drawing_area();
    root.fill(&WHITE)?;
    let largest_time = points.iter().map(|p| p.time_relative_to_f64).fold(1.0, f64::max);
    let largest_percent = points.iter().map(|p| p.percent_differing).fold(PERCENT_FLOOR * 10.0, f64::max);
    let mut chart = ChartBuilder::on(&root)
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
        .y_label_formatter(&|value| if *value <= PERCENT_FLOOR * 1.0001 { "0 (identical)".into() } else { format!("{value}") })
        .draw()?;
    for (position, group) in groups.iter().enumerate() {
        // f64 is the reference, at (1, 0) in every group: drawn once, below.
        let in_group = points.iter().filter(|p| p.group == *group && p.number != "f64");
        let at = |p: &PlotPoint| (p.time_relative_to_f64, p.percent_differing.max(PERCENT_FLOOR));
        let series = chart.draw_series(in_group.clone().map(|p| -> DynElement<BitMapBackend, (f64, f64)> {
            let style = number_colour(p.number).filled();
            match position % 3 {
                0 => Circle::new(at(p), 6, style).into_dyn(),
                1 => TriangleMarker::new(at(p), 8, style).into_dyn(),
                _ => Cross::new(at(p), 7, number_colour(p.number).stroke_width(3)).into_dyn(),
            }
        }))?;
        series.label(*group).legend(move |(x, y)| -> DynElement<BitMapBackend, (i32, i32)> {
            let style = BLACK.filled();
            match position % 3 {
                0 => Circle::new((x, y), 5, style).into_dyn(),
                1 => TriangleMarker::new((x, y), 7, style).into_dyn(),
                _ => Cross::new((x, y), 6, BLACK.stroke_width(3)).into_dyn(),
            }
        });
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
    root.present()?;
    Ok(())
}
