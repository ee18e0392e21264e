//! `microtrace view SCENE.mts`: watch a scene render in a simulator window (issue 6).
//!
//! The image is traced by the same core through the same `PixelSink`/`PixelSource` path as the
//! firmware and appears row by row from the top; the panel shows the settings, the statistics
//! and the render time, the key help, and a preview of a display the firmware drives (the
//! 128x64 grey OLED, a 1-bit SSD1306 through the dither, a 240x240 RGB565 panel). The
//! overlay draws what the optimizations see: extents and grid cells on the image, and beside
//! the panel a plan view of the bounding volumes with Sortlist's depth ranges. `T` and `A`
//! cycle the ray tree's depth and the antialiasing (chapter 5), and the panel shows the rays
//! per pixel and the secondary rays they cost.

use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Context;
use embedded_graphics::pixelcolor::Rgb888 as EgRgb888;
use embedded_graphics::mono_font::ascii::FONT_6X10;
use embedded_graphics::mono_font::MonoTextStyle;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::text::{Baseline, Text};
use embedded_graphics_simulator::sdl2::Keycode;
use embedded_graphics_simulator::{OutputSettings, OutputSettingsBuilder, SimulatorDisplay, SimulatorEvent};
use microtrace::pixel::FrameBuffer;
use microtrace::render::{PassStatistics, Pga, Progressive, Rgb, Statistics, Whole};
use microtrace::model::{Antialias, Optimizations};

use crate::commands::render::statistics_table;
use crate::files;
use microtrace::number::NumberKind;
use crate::rendering::{Mode, Pixels, Rendered};
use crate::scene_file::{self, HostScene, SceneOptions};
use crate::heap::HostPrepared;
use microtrace::with_number_kind;

#[path = "../view/mod.rs"]
pub mod ui;

use ui::keys::{self, Action};
use ui::fill::PixelbufferFill;
use ui::overlay::ScreenExtent;
use ui::plan::PlanView;
use ui::preview::DisplayKind;
use ui::rays;
use ui::window::View;

#[derive(clap::Args, Clone, Debug)]
pub struct ViewArgs {
    /// The scene to show (.mts, or NFF: .nff, .nff.gz).
    pub scene: PathBuf,
    /// The number type (N cycles it in the window), the mode (M switches it) and the scene's
    /// overrides, as `render` takes them.
    #[command(flatten)]
    pub options: SceneOptions,
    /// Show each window pixel as N x N screen pixels (for small scenes).
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=16))]
    pub scale: u32,
    /// Start with the optimization overlay on: extents, grid and plan view (O toggles it).
    #[arg(long)]
    pub overlay: bool,
    /// Start with the pixels the Pixelbuffer's fill marks tinted (F toggles it).
    #[arg(long)]
    pub fill: bool,
    /// Trace coarse to fine: 8x8 blocks, then 4x4, 2x2 and every pixel (C toggles it).
    #[arg(long)]
    pub progressive: bool,
    /// The display previewed beside the image (L cycles them).
    #[arg(long, value_enum, default_value = "oled")]
    pub display: DisplayKind,
    /// Render fully, save the finished window (image, overlay, panel) to FILE.png and exit.
    #[arg(long, value_name = "FILE.png")]
    pub screenshot: Option<PathBuf>,
    /// Close the window when the render has finished.
    #[arg(long)]
    pub exit_when_done: bool,
    /// Press these keys once the first render has finished, one after another as if typed,
    /// each re-rendering as it would (e.g. `TTA`: depth up twice, antialiasing on);
    /// --screenshot and --exit-when-done apply after the last. For scripts and tests.
    #[arg(long, value_name = "KEYS", value_parser = keys::parse_script)]
    pub keys: Option<keys::Script>,
}

/// What the keys change.
struct Settings {
    number: NumberKind,
    mode: Mode,
    overlay: bool,
    fill: bool,
    /// Show the edge image (`E`) instead of the picture.
    edges: bool,
    progressive: bool,
    display: DisplayKind,
    /// The threshold `A` turns antialiasing on with: the scene's, else [`rays::DEFAULT_THRESHOLD`].
    threshold: f64,
}

/// What a key changed, and so what has to be done again.
enum Change {
    /// The image: render again.
    Image,
    /// Only what is drawn over and beside it: draw the window again.
    Window,
    /// Nothing (the change was refused, with the reason on stderr).
    Nothing,
    SavePng,
    Quit,
}

/// One finished render: the image, its statistics and what the overlay draws.
struct Finished {
    rendered: Rendered,
    extents: Vec<ScreenExtent>,
    /// Each solid's enclosure tree (§3.3.6).
    enclosures: Vec<ui::enclosures::NodeBox>,
    grid: ui::overlay::GridLines,
    plan: PlanView,
    fill: PixelbufferFill,
}

/// Where the Grid's cells start (from `Acceleration::grid_cell`); empty without the Grid.
fn grid_lines<C: microtrace::config::Config>(acceleration: &microtrace::optimize::Acceleration<C>, width: u16, height: u16) -> ui::overlay::GridLines {
    let at = |column, row| microtrace::camera::PixelPosition { column, row, screen_x: 0, screen_y: 0 };
    let columns = (1..width).filter(|&x| acceleration.grid_cell(at(x, 0)).is_some_and(|(_, _, dx, _)| dx == 0)).collect();
    let rows = (1..height).filter(|&y| acceleration.grid_cell(at(0, y)).is_some_and(|(_, _, _, dy)| dy == 0)).collect();
    ui::overlay::GridLines { columns, rows, width, height }
}

pub fn run(args: ViewArgs) -> anyhow::Result<()> {
    let mut scene = scene_file::load(&args.scene)?;
    args.options.apply(&mut scene);
    let (width, height) = (u32::from(scene.viewport.width()), u32::from(scene.viewport.height()));
    let panel_x = width + 8;
    let panel_height = DisplayKind::tallest() + 12 + ui::panel::height(PANEL_LINES);
    let plan_height = PLAN_TOP + ui::plan::HEIGHT + 8 + ui::depth_ranges::height(scene.objects.len()) + 4;
    let window_size = Size::new(panel_x + ui::panel::WIDTH + ui::plan::WIDTH + 8, height.max(panel_height).max(plan_height));
    let mut display = SimulatorDisplay::<EgRgb888>::new(window_size);
    let output = OutputSettingsBuilder::new().scale(args.scale).build();
    let title = format!("MicroTrace — {}", args.scene.display());
    let mut view = View::open(&title, &output, &display)?;
    let mut settings = Settings {
        number: args.options.number,
        mode: args.options.mode,
        overlay: args.overlay,
        edges: false,
        fill: args.fill,
        progressive: args.progressive,
        display: args.display,
        threshold: scene.antialias.map_or(rays::DEFAULT_THRESHOLD, |antialias| antialias.threshold),
    };
    let mut script: VecDeque<Keycode> = args.keys.clone().map(|script| script.0).unwrap_or_default().into();

    loop {
        let finished = render(&scene, &settings, &mut display, &mut view).map_err(|error| scene_file::in_file(&args.scene, error))?;
        eprint!("{}", statistics_table(&finished.rendered));
        eprintln!(
            "preprocess {:.1} ms, trace {:.1} ms ({} {} {})",
            finished.rendered.preprocess.as_secs_f64() * 1e3,
            finished.rendered.trace.as_secs_f64() * 1e3,
            settings.number.name(),
            mode_name(settings.mode),
            optimization_names(scene.optimizations)
        );
        // The panel's ray lines, for scripts: `--keys` then reads what the panel shows.
        let ray_lines = ray_lines(&scene, &finished.rendered);
        eprintln!("{}", ray_lines.iter().map(|line| line.trim()).filter(|line| !line.is_empty()).collect::<Vec<_>>().join("; "));
        let mut preview = ui::preview::render(&scene, settings.number, settings.display).map_err(|error| scene_file::in_file(&args.scene, error))?;
        draw_finished(&scene, &settings, &finished, &preview, &mut display, Point::new(panel_x as i32, 4));
        view.update(&display);
        // Wait for a key that changes something: the script's next, else the window's.
        'waiting: loop {
            let actions: Vec<Action> = match script.pop_front() {
                Some(key) => keys::action(key).into_iter().collect(),
                None => {
                    if let Some(path) = &args.screenshot {
                        display
                            .to_rgb_output_image(&OutputSettings::default())
                            .save_png(path)
                            .with_context(|| format!("cannot write the screenshot {}", path.display()))?;
                        eprintln!("screenshot written to {}", path.display());
                        return Ok(());
                    }
                    if args.exit_when_done {
                        return Ok(());
                    }
                    let mut actions = Vec::new();
                    for event in view.update(&display) {
                        match event {
                            SimulatorEvent::Quit => return Ok(()),
                            SimulatorEvent::KeyDown { keycode, repeat: false, .. } => actions.extend(keys::action(keycode)),
                            _ => {}
                        }
                    }
                    actions
                }
            };
            for action in actions {
                match apply(action, &mut scene, &mut settings, &args.scene) {
                    Change::Quit => return Ok(()),
                    Change::Image => break 'waiting,
                    Change::Window => {
                        if action == Action::CycleDisplay {
                            preview = ui::preview::render(&scene, settings.number, settings.display).map_err(|error| scene_file::in_file(&args.scene, error))?;
                        }
                        draw_finished(&scene, &settings, &finished, &preview, &mut display, Point::new(panel_x as i32, 4));
                    }
                    Change::SavePng => save_png(&args, &finished.rendered),
                    Change::Nothing => {}
                }
            }
        }
    }
}

/// Applies what a key does to the scene and the settings.
fn apply(action: Action, scene: &mut HostScene, settings: &mut Settings, path: &Path) -> Change {
    let o = &mut scene.optimizations;
    match action {
        Action::Quit => return Change::Quit,
        Action::TogglePixelbuffer => o.pixelbuffer = !o.pixelbuffer,
        Action::ToggleExtents => o.extents = !o.extents,
        Action::ToggleGrid => o.grid = !o.grid,
        Action::ToggleSortlist => o.sortlist = !o.sortlist,
        Action::CycleNumber => match next_number_type(scene, settings.number, path) {
            Some(number) => settings.number = number,
            None => return Change::Nothing,
        },
        Action::SwitchMode => settings.mode = if settings.mode == Mode::Pga { Mode::Rgb } else { Mode::Pga },
        Action::ToggleDither => scene.dither = !scene.dither,
        Action::ToggleShadows => scene.shadows = !scene.shadows,
        Action::ToggleProgressive => settings.progressive = !settings.progressive,
        Action::CycleDepth => scene.depth = rays::next_depth(scene.depth),
        Action::CycleAntialias => match next_antialias(scene, settings, path) {
            Some(antialias) => scene.antialias = antialias,
            None => return Change::Nothing,
        },
        Action::ToggleOverlay => {
            settings.overlay = !settings.overlay;
            return Change::Window;
        }
        Action::ToggleFill => {
            settings.fill = !settings.fill;
            return Change::Window;
        }
        Action::ToggleEdges => {
            settings.edges = !settings.edges;
            return Change::Window;
        }
        Action::CycleDisplay => {
            settings.display = settings.display.next();
            return Change::Window;
        }
        Action::SavePng => return Change::SavePng,
    }
    Change::Image
}

/// Whether the scene prepares in `number`, with the preparation error naming the file if not.
fn prepares(scene: &HostScene, number: NumberKind, path: &Path) -> Result<(), scene_file::SceneFileError> {
    let prepared = with_number_kind!(number, N => HostPrepared::<N>::prepare(scene).map(|_| ()));
    prepared.map_err(|error| scene_file::SceneFileError { path: path.to_owned(), error })
}

/// The next antialiasing in `A`'s cycle (off, L1..L4 at the settings' threshold) that the scene
/// prepares with in the current number type; the levels it does not (a sample grid beyond the
/// camera's range) are skipped with the reason on stderr. `None`: none does.
fn next_antialias(scene: &HostScene, settings: &Settings, path: &Path) -> Option<Option<Antialias>> {
    let mut trial = Box::new(scene.clone());
    for _ in 0..=rays::MAX_LEVELS {
        trial.antialias = rays::next_antialias(trial.antialias, settings.threshold);
        match prepares(&trial, settings.number, path) {
            Ok(()) => return Some(trial.antialias),
            Err(error) => eprintln!("microtrace: skipping {}: {error}", rays::antialias_label(trial.antialias)),
        }
    }
    None
}

/// The panel's lines about the rays (see [`rays::lines`]).
fn ray_lines(scene: &HostScene, rendered: &Rendered) -> [String; rays::LINES] {
    let pixels = u64::from(rendered.width()) * u64::from(rendered.height());
    rays::lines(scene.depth, scene.antialias, &rendered.statistics, pixels)
}

/// The next number type after `current` that can represent the scene; the ones that cannot
/// (beyond a fixed-point type's range) are skipped with their preparation error on stderr,
/// rather than ending the window.
fn next_number_type(scene: &HostScene, current: NumberKind, path: &Path) -> Option<NumberKind> {
    let all = NumberKind::ALL;
    let at = all.iter().position(|n| *n == current).unwrap_or(0);
    (1..all.len()).map(|step| all[(at + step) % all.len()]).find(|&number| match prepares(scene, number, path) {
        Ok(()) => true,
        Err(error) => {
            eprintln!("microtrace: skipping {}: {error}", number.name());
            false
        }
    })
}

fn mode_name(mode: Mode) -> &'static str {
    match mode {
        Mode::Pga => "PGA",
        Mode::Rgb => "RGB",
    }
}

fn optimization_names(o: Optimizations) -> String {
    let names: Vec<&str> = [(o.pixelbuffer, "Pb"), (o.extents, "Ex"), (o.grid, "Gd"), (o.sortlist, "Sl")]
        .iter()
        .filter_map(|(on, name)| on.then_some(*name))
        .collect();
    if names.is_empty() { "no optimizations".into() } else { names.join(",") }
}

/// Saves the image (not the panel) next to the scene, numbered so no file is overwritten.
fn save_png(args: &ViewArgs, rendered: &Rendered) {
    let stem = args.scene.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "view".into());
    let path = (1..).map(|n| PathBuf::from(format!("{stem}-view-{n}.png"))).find(|p| !p.exists()).expect("a free name");
    match files::write_png_rgb(&path, rendered.width(), rendered.height(), &rendered.to_rgb()) {
        Ok(()) => eprintln!("saved {}", path.display()),
        Err(error) => eprintln!("microtrace: cannot write {}: {error}", path.display()),
    }
}

/// Clears the window and traces the scene into it row by row, updating the window as it goes.
fn render(scene: &HostScene, settings: &Settings, display: &mut SimulatorDisplay<EgRgb888>, view: &mut View) -> anyhow::Result<Finished> {
    let _ = display.clear(EgRgb888::BLACK);
    view.update(display);
    let viewport = scene.viewport;
    let (width, height) = (viewport.width(), viewport.height());
    let count = usize::from(width) * usize::from(height);
    let palette = scene.palette;
    with_number_kind!(settings.number, N => {
        let started = Instant::now();
        let prepared = Box::new(HostPrepared::<N>::prepare(scene).map_err(|error| anyhow::anyhow!("{error}"))?);
        let preprocess = started.elapsed();
        // With antialiasing the optimizations serve the sample grid (`step` samples a pixel
        // side): its columns and rows are drawn at the pixels they fall in.
        let step = prepared.antialias.map_or(1, |antialias| antialias.step());
        let pixel = |sample: u16, pixels: u16| (sample / step).min(pixels.saturating_sub(1));
        let extents = (0..scene.objects.len())
            .filter_map(|object| prepared.acceleration.extent(object).map(|e| (object, e)))
            .map(|(object, e)| ScreenExtent {
                object,
                columns: (pixel(e.first_column, width), pixel(e.last_column, width)),
                rows: (pixel(e.first_row, height), pixel(e.last_row, height)),
            })
            .collect();
        let enclosures = ui::enclosures::enclosure_trees(scene, &prepared.camera, step);
        let mut grid = grid_lines(&prepared.acceleration, prepared.camera.width(), prepared.camera.height());
        if step > 1 {
            let to_pixels = |lines: &mut Vec<u16>, pixels: u16| {
                lines.iter_mut().for_each(|line| *line = pixel(*line, pixels));
                lines.retain(|line| *line > 0);
                lines.dedup();
            };
            to_pixels(&mut grid.columns, width);
            to_pixels(&mut grid.rows, height);
            (grid.width, grid.height) = (width, height);
        }
        let plan = PlanView::of(&*prepared);
        let mut fill = PixelbufferFill::record(&*prepared);
        if prepared.antialias.is_some() {
            fill = fill.of_pixels(step, width, height);
        }
        let mut statistics = Statistics::default();
        // Progressive: the passes go straight to the window, each drawn as it finishes.
        let mut passes = settings.progressive.then(PassStatistics::default);
        let started = Instant::now();
        let pixels = match settings.mode {
            Mode::Pga => {
                let mut buffer = vec![0u8; count];
                let frame = FrameBuffer::new(&mut buffer, width, height).expect("buffer sized to the viewport");
                let mut sink = ui::sink::WindowSink::new(frame, display, &palette, Some(view));
                match &mut passes {
                    Some(passes) => microtrace::render::render(&*prepared, Pga, Progressive, &mut sink, passes),
                    None => microtrace::render::render(&*prepared, Pga, Whole, &mut sink, &mut statistics),
                }
                Pixels::Pga(buffer)
            }
            Mode::Rgb => {
                let mut buffer = vec![[0u8; 3]; count];
                let frame = FrameBuffer::new(&mut buffer, width, height).expect("buffer sized to the viewport");
                let mut sink = ui::sink::WindowSink::new(frame, display, &palette, Some(view));
                match &mut passes {
                    Some(passes) => microtrace::render::render(&*prepared, Rgb, Progressive, &mut sink, passes),
                    None => microtrace::render::render(&*prepared, Rgb, Whole, &mut sink, &mut statistics),
                }
                Pixels::Rgb(buffer)
            }
        };
        if let Some(passes) = &passes {
            statistics = passes.total();
        }
        let trace = started.elapsed();
        Ok(Finished { rendered: Rendered { viewport, palette, pixels, statistics, passes, preprocess, trace }, extents, enclosures, grid, plan, fill })
    })
}

/// Redraws the image (with the overlay if on), the display preview and the panel.
fn draw_finished(
    scene: &HostScene,
    settings: &Settings,
    finished: &Finished,
    preview: &ui::preview::Preview,
    display: &mut SimulatorDisplay<EgRgb888>,
    panel: Point,
) {
    let _ = display.clear(EgRgb888::BLACK);
    let rendered = &finished.rendered;
    let width = usize::from(rendered.width());
    // The edge image (E) in place of the picture: black lines where the first surface changes.
    let edges = settings.edges.then(|| crate::edges::first_surfaces(scene, settings.number).ok()).flatten();
    let colours: Vec<[u8; 3]> = match &edges {
        Some(surfaces) => crate::edges::edges(surfaces, width).into_iter().map(|edge| if edge { [0; 3] } else { [255; 3] }).collect(),
        None => rendered.to_rgb(),
    };
    let pixels = colours.into_iter().enumerate().map(|(i, [r, g, b])| Pixel(Point::new((i % width) as i32, (i / width) as i32), EgRgb888::new(r, g, b)));
    let _ = display.draw_iter(pixels);
    if settings.fill {
        finished.fill.draw_tint(display);
    }
    // The plan view and the depth ranges go right of the panel.
    let left = panel.x + ui::panel::WIDTH as i32;
    let text = MonoTextStyle::new(&FONT_6X10, EgRgb888::new(230, 230, 230));
    if settings.overlay {
        ui::overlay::draw_grid(&finished.grid, display);
        ui::overlay::draw(&finished.extents, display);
        ui::enclosures::draw(&finished.enclosures, display);
        let _ = Text::with_baseline("plan x-z from above: volumes", Point::new(left, panel.y), text, Baseline::Top).draw(display);
        let area = Rectangle::new(Point::new(left, PLAN_TOP as i32), Size::new(ui::plan::WIDTH, ui::plan::HEIGHT));
        ui::plan::draw(&finished.plan, display, area);
        let below = Point::new(left, (PLAN_TOP + ui::plan::HEIGHT + 8) as i32);
        ui::depth_ranges::draw(&finished.plan, display, below, ui::plan::WIDTH);
    } else {
        let _ = Text::with_baseline("O: overlay, plan view here", Point::new(left, panel.y), text, Baseline::Top).draw(display);
    }
    ui::preview::draw(preview, display, panel + Point::new(1, 1));
    let s = &rendered.statistics;
    let [tree, per_pixel, secondary, generations] = ray_lines(scene, rendered);
    let lines = vec![
        format!("{} (above)", preview.kind.label()),
        format!("{}x{} {} {}", rendered.width(), rendered.height(), settings.number.name(), mode_name(settings.mode)),
        format!("opt {}", optimization_names(scene.optimizations)),
        format!("shadows {}  dither {}", on(scene.shadows), on(scene.dither)),
        tree,
        format!("overlay {}  fill {} ({} px)  edges {}", on(settings.overlay), on(settings.fill), finished.fill.count(), on(settings.edges)),
        format!("preprocess {:.1} ms", rendered.preprocess.as_secs_f64() * 1e3),
        format!("trace      {:.1} ms", rendered.trace.as_secs_f64() * 1e3),
        format!("pixels {}  traced {}", s.pixels, s.rays_traced),
        format!("ray-object tests {}", s.ro_tests),
        format!("ray-object hits  {}", s.ro_hits),
        format!("shadow rays {} tests {}", s.shadow_rays, s.shadow_tests),
        per_pixel,
        secondary,
        generations,
        match &rendered.passes {
            Some(passes) => format!("progressive, rays {}", passes.passes.map(|p| p.rays_traced.to_string()).join("/")),
            None => "progressive off".to_owned(),
        },
    ];
    let y = panel.y + preview.kind.shown_size().height as i32 + 8;
    ui::panel::draw(&lines, display, Point::new(panel.x, y));
}

/// Lines of text in the panel above the key help.
const PANEL_LINES: usize = 12 + rays::LINES;
/// Top of the plan view's drawing area (below its title).
const PLAN_TOP: u32 = 4 + 12;

fn on(value: bool) -> &'static str {
    if value { "on" } else { "off" }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cycling_the_number_type_skips_the_types_the_scene_is_beyond() {
        // Beyond fixed16's ±16 384 (the window) but within fixed's ±26 000.
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/hard/large_coordinates.mts");
        let scene = scene_file::load(&path).unwrap();
        assert_eq!(next_number_type(&scene, NumberKind::F32, &path), Some(NumberKind::Fixed));
        assert_eq!(next_number_type(&scene, NumberKind::Fixed, &path), Some(NumberKind::F32Micromath));
    }
}
