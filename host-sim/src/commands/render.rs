//! `microtrace render SCENE.mts --out IMAGE.png`: render a scene to a PNG and/or the thesis's
//! file formats. Every file is written whole or not at all.

use std::num::NonZeroUsize;
use std::path::PathBuf;

use anyhow::{bail, Context};

use crate::files;
use crate::rendering::{render_scene_on_threads, render_scene_progressive, Mode, Pixels, Rendered};
use microtrace::render::PASS_SIZES;
use crate::scene_file::{self, SceneOptions};
use crate::commands::view::ui::preview::{self, DisplayKind};
use embedded_graphics::pixelcolor::RgbColor;

#[derive(clap::Args, Clone, Debug)]
pub struct RenderArgs {
    /// The scene (.mts, or NFF: .nff, .nff.gz).
    pub scene: PathBuf,
    /// Write the image as a PNG.
    #[arg(long, value_name = "IMAGE.png")]
    pub out: Option<PathBuf>,
    /// The number type, the mode and the scene's overrides (shared with `view`).
    #[command(flatten)]
    pub options: SceneOptions,
    /// Write the thesis's PGA image file (compressed 0xD9 records unless --uncompressed).
    #[arg(long, value_name = "FILE")]
    pub pga: Option<PathBuf>,
    /// With --pga: write the uncompressed 0xFF format.
    #[arg(long, requires = "pga")]
    pub uncompressed: bool,
    /// Write the thesis's RGB image file (0x00 format; needs --mode rgb).
    #[arg(long, value_name = "FILE")]
    pub rgb: Option<PathBuf>,
    /// Write the scene's 256-entry look-up table file.
    #[arg(long, value_name = "FILE")]
    pub lut: Option<PathBuf>,
    /// Print the statistics of the thesis's Table 4.2 on stderr.
    #[arg(long)]
    pub stats: bool,
    /// Write the statistics as JSON.
    #[arg(long, value_name = "FILE")]
    pub stats_json: Option<PathBuf>,
    /// Render on N threads, in bands of rows (default: one per core). 1 is the plain
    /// single-threaded render; with more the image is the same, the statistics the sum over bands.
    #[arg(long, value_name = "N", value_parser = parse_threads)]
    pub threads: Option<NonZeroUsize>,
    /// Trace coarse to fine, as on a slow chip: one pixel of each 8x8 block drawn as the block,
    /// then 4x4, 2x2 and every pixel (one thread). The same image; the statistics per pass.
    #[arg(long, conflicts_with = "threads")]
    pub progressive: bool,
    /// Write, as --out, the picture a display the firmware drives shows: the scene fitted to the
    /// display and each finished row sent through that display's mapping, as the firmware and the
    /// real-board examples do (the window's display preview; docs/simulator.md).
    #[arg(long, value_enum, value_name = "KIND", requires = "out", conflicts_with_all = ["pga", "rgb", "lut", "stats", "stats_json", "progressive", "size"])]
    pub display: Option<DisplayKind>,
    /// Write, as --out, the edge image instead of the picture (Roth, thesis §3.3): a black line
    /// where a pixel's first surface differs from its left or upper neighbour's, on white.
    #[arg(long, requires = "out", conflicts_with_all = ["pga", "rgb", "lut", "stats", "stats_json", "progressive", "display"])]
    pub edges: bool,
}

/// Parses a thread count of at least 1.
fn parse_threads(text: &str) -> Result<NonZeroUsize, String> {
    let count: usize = text.trim().parse().map_err(|_| format!("`{text}` is not a thread count: give a whole number from 1 up"))?;
    NonZeroUsize::new(count).ok_or_else(|| "the thread count must be at least 1".to_owned())
}

/// One thread per core, or one where the core count is unknown.
fn default_threads() -> NonZeroUsize {
    std::thread::available_parallelism().unwrap_or(NonZeroUsize::MIN)
}

pub fn run(args: RenderArgs) -> anyhow::Result<()> {
    if args.out.is_none() && args.pga.is_none() && args.rgb.is_none() && args.lut.is_none() && !args.stats && args.stats_json.is_none() {
        bail!("nothing to write: give --out IMAGE.png (or --pga, --rgb, --lut, --stats, --stats-json)");
    }
    if args.pga.is_some() && args.options.mode != Mode::Pga {
        bail!("--pga writes palette indices: it needs --mode pga");
    }
    if args.rgb.is_some() && args.options.mode != Mode::Rgb {
        bail!("--rgb writes the RGB file format: it needs --mode rgb");
    }
    let mut scene = scene_file::load(&args.scene)?;
    args.options.apply(&mut scene);
    if let (Some(kind), Some(path)) = (args.display, &args.out) {
        let shown = preview::render(&scene, args.options.number, kind).map_err(|error| scene_file::in_file(&args.scene, error))?;
        let (width, height) = kind.size();
        let rgb: Vec<[u8; 3]> = shown.pixels.iter().map(|colour| [colour.r(), colour.g(), colour.b()]).collect();
        return files::write_png_rgb(path, width, height, &rgb).with_context(|| format!("cannot write {}", path.display()));
    }
    if let (true, Some(path)) = (args.edges, &args.out) {
        let surfaces = crate::edges::first_surfaces(&scene, args.options.number).map_err(|error| scene_file::in_file(&args.scene, error.into()))?;
        let (width, height) = (scene.viewport.width(), scene.viewport.height());
        let rgb: Vec<[u8; 3]> = crate::edges::edges(&surfaces, usize::from(width)).into_iter().map(|edge| if edge { [0; 3] } else { [255; 3] }).collect();
        return files::write_png_rgb(path, width, height, &rgb).with_context(|| format!("cannot write {}", path.display()));
    }
    let label = format!("rendering {}", args.scene.display());
    let threads = args.threads.unwrap_or_else(default_threads);
    let rendered = if args.progressive {
        render_scene_progressive(&scene, args.options.number, args.options.mode, Some(&label))
    } else {
        render_scene_on_threads(&scene, args.options.number, args.options.mode, Some(&label), threads)
    };
    let rendered = rendered
        .map_err(|error| match error.downcast::<microtrace::model::SceneError>() {
            Ok(error) => scene_file::SceneFileError { path: args.scene.clone(), error }.into(),
            Err(other) => other.context(format!("cannot render {}", args.scene.display())),
        })?;
    scene_file::warn(&args.scene, &scene);
    write_outputs(&args, &rendered)
}

fn write_outputs(args: &RenderArgs, rendered: &Rendered) -> anyhow::Result<()> {
    let (width, height) = (rendered.width(), rendered.height());
    if let Some(path) = &args.out {
        let written = match &rendered.pixels {
            Pixels::Pga(indices) => files::write_png_indexed(path, width, height, indices, &rendered.palette),
            Pixels::Rgb(rgb) => files::write_png_rgb(path, width, height, rgb),
        };
        written.with_context(|| format!("cannot write {}", path.display()))?;
    }
    if let (Some(path), Pixels::Pga(indices)) = (&args.pga, &rendered.pixels) {
        let written = if args.uncompressed {
            files::write_pga_uncompressed(path, rendered.viewport, indices)
        } else {
            files::write_pga_compressed(path, rendered.viewport, indices)
        };
        written.with_context(|| format!("cannot write {}", path.display()))?;
    }
    if let (Some(path), Pixels::Rgb(rgb)) = (&args.rgb, &rendered.pixels) {
        files::write_rgb_file(path, rendered.viewport, rgb).with_context(|| format!("cannot write {}", path.display()))?;
    }
    if let Some(path) = &args.lut {
        files::write_lut_file(path, &rendered.palette).with_context(|| format!("cannot write {}", path.display()))?;
    }
    if args.stats {
        eprint!("{}", statistics_table(rendered));
    }
    if let Some(path) = &args.stats_json {
        let json = statistics_json(rendered);
        files::write_atomically(path, |out| out.write_all(json.as_bytes()))
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
}

/// The statistics as JSON with the keys of Table 4.2 (and the shadow counts).
/// A progressive render adds `passes`: each pass's block size and counts.
pub fn statistics_json(rendered: &Rendered) -> String {
    let s = &rendered.statistics;
    let passes = match &rendered.passes {
        None => String::new(),
        Some(passes) => {
            let each: Vec<String> = passes
                .passes
                .iter()
                .zip(PASS_SIZES)
                .map(|(p, size)| {
                    format!(
                        "{{\"block\": {size}, \"pixels\": {}, \"rays_traced\": {}, \"rays_intersected\": {}, \"ro_tests\": {}, \"shadow_rays\": {}}}",
                        p.pixels, p.rays_traced, p.rays_intersected, p.ro_tests, p.shadow_rays
                    )
                })
                .collect();
            format!(", \"passes\": [{}]", each.join(", "))
        }
    };
    format!(
        "{{\"pixels\": {}, \"rays_traced\": {}, \"rays_intersected\": {}, \"ro_tests\": {}, \"ro_hits\": {}, \
         \"shadow_rays\": {}, \"shadow_tests\": {}, \"solid_leaf_tests\": {}, \"preprocess_ms\": {:.3}, \"trace_ms\": {:.3}{passes}}}\n",
        s.pixels,
        s.rays_traced,
        s.rays_intersected,
        s.ro_tests,
        s.ro_hits,
        s.shadow_rays,
        s.shadow_tests,
        s.solid_leaf_tests,
        rendered.preprocess.as_secs_f64() * 1e3,
        rendered.trace.as_secs_f64() * 1e3,
    )
}

/// Table 4.2's figures as the thesis defines them (digest §9.1); for a progressive render,
/// then the rays each pass traced.
pub fn statistics_table(rendered: &Rendered) -> String {
    let mut table = thesis_table(rendered);
    if let Some(passes) = &rendered.passes {
        for (pass, (p, size)) in passes.passes.iter().zip(PASS_SIZES).enumerate() {
            table += &format!("pass {} ({size}x{size})    {} rays, {} pixels\n", pass + 1, p.rays_traced, p.pixels);
        }
    }
    table
}

fn thesis_table(rendered: &Rendered) -> String {
    let s = &rendered.statistics;
    let percent = |part: u64, whole: u64| if whole == 0 { 0.0 } else { 100.0 * part as f64 / whole as f64 };
    let per = |part: u64, whole: u64| if whole == 0 { 0.0 } else { part as f64 / whole as f64 };
    let mut table = format!(
        "pixels            {}\n\
         rays traced       {:.2}%\n\
         rays intersected  {:.2}%\n\
         R-O tests per ray {:.2}\n\
         % hits            {:.2}%\n\
         total R-O tests   {}\n\
         shadow rays       {}\n\
         shadow tests      {} ({:.2} per shadow ray)\n",
        s.pixels,
        percent(s.rays_traced, s.pixels),
        percent(s.rays_intersected, s.rays_traced),
        per(s.ro_tests, s.rays_traced),
        percent(s.ro_hits, s.ro_tests),
        s.ro_tests,
        s.shadow_rays,
        s.shadow_tests,
        per(s.shadow_tests, s.shadow_rays),
    );
    // Solids (chapter 3): the primitives their tests met inside them.
    if s.solid_leaf_tests > 0 {
        table.push_str(&format!("solid leaf tests  {} (primitives tested inside solids, by every kind of ray)\n", s.solid_leaf_tests));
    }
    // Antialiasing traces more than one ray a pixel (chapter 5).
    if s.rays_traced > s.pixels {
        table.push_str(&format!("rays per pixel    {:.2}\n", per(s.rays_traced, s.pixels)));
    }
    // The ray tree (chapter 5), when the scene has one.
    let secondary = s.secondary_rays_total();
    if secondary > 0 {
        let generations: Vec<String> = s.secondary_rays.iter().take_while(|count| **count > 0).map(u64::to_string).collect();
        table.push_str(&format!(
            "secondary rays    {secondary} (by generation after the primary: {})\n\
             secondary tests   {} ({:.2} per secondary ray)\n",
            generations.join(", "),
            s.secondary_tests,
            per(s.secondary_tests, secondary),
        ));
    }
    table.push_str(&format!(
        "preprocess        {:.1} ms\n\
         trace             {:.1} ms\n",
        rendered.preprocess.as_secs_f64() * 1e3,
        rendered.trace.as_secs_f64() * 1e3,
    ));
    table
}
