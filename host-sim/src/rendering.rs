//! Rendering a scene description into memory with a chosen number type and mode, timing the
//! preprocess and trace phases separately (Table 4.2's two times).

use std::num::NonZeroUsize;
use std::time::{Duration, Instant};

use anyhow::bail;
use clap::ValueEnum;
use microtrace::model::Rgb888;
use microtrace::pixel::FrameBuffer;
use microtrace::render::{PASSES, PassStatistics, Pga, Progressive, Rgb, Rows, Statistics, Whole, render};
use microtrace::number::Number;
use microtrace::model::SceneError;
use microtrace::model::Viewport;
use microtrace::model::Palette;

use microtrace::number::NumberKind;
use crate::parallel::render_in_bands;
use crate::progress::{Progress, ProgressReport};
use crate::heap::HostPrepared;
use crate::scene_file::HostScene;
use microtrace::with_number_kind;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Mode {
    /// Palette indices through the 256-entry look-up table (the thesis's default).
    Pga,
    /// 24-bit colour.
    Rgb,
}

#[derive(Clone, Debug)]
pub enum Pixels {
    Pga(Vec<u8>),
    Rgb(Vec<Rgb888>),
}

#[derive(Clone, Debug)]
pub struct Rendered {
    pub viewport: Viewport,
    pub palette: Palette,
    pub pixels: Pixels,
    pub statistics: Statistics,
    /// Each pass's statistics, for a progressive render (`statistics` is then their sum).
    pub passes: Option<PassStatistics>,
    pub preprocess: Duration,
    pub trace: Duration,
}

impl Rendered {
    pub fn width(&self) -> u16 {
        self.viewport.width()
    }

    pub fn height(&self) -> u16 {
        self.viewport.height()
    }

    /// The image as RGB, indexed pixels through the look-up table.
    pub fn to_rgb(&self) -> Vec<Rgb888> {
        match &self.pixels {
            Pixels::Pga(indices) => indices.iter().map(|index| self.palette.entry(*index).to_rgb888()).collect(),
            Pixels::Rgb(rgb) => rgb.clone(),
        }
    }
}

/// Prepares `scene` in the number type `N`, every table on the heap and sized by the scene.
pub fn prepare_host<N: Number>(scene: &HostScene) -> Result<HostPrepared<N>, SceneError> {
    HostPrepared::<N>::prepare(scene)
}

/// Prepares and renders `scene` on this thread alone. With `progress` set, shows progress on a
/// terminal.
pub fn render_scene(scene: &HostScene, number: NumberKind, mode: Mode, progress: Option<&str>) -> anyhow::Result<Rendered> {
    render_scene_on_threads(scene, number, mode, progress, NonZeroUsize::MIN)
}

/// [`render_scene`] on `threads` threads, in bands of rows (see [`crate::parallel`]). One thread
/// is the plain whole-image render; with more, the image is the same and the statistics are the
/// sum over bands.
pub fn render_scene_on_threads(
    scene: &HostScene,
    number: NumberKind,
    mode: Mode,
    progress: Option<&str>,
    threads: NonZeroUsize,
) -> anyhow::Result<Rendered> {
    let viewport = scene.viewport;
    let (width, height) = (viewport.width(), viewport.height());
    let pixel_count = usize::from(width) * usize::from(height);
    if pixel_count > 64 << 20 {
        bail!("the viewport is {width}x{height}: too large to render in memory");
    }
    let single_threaded = threads.get() == 1;
    // The scene error stays typed (not just its text) so callers can tell "out of range" apart.
    with_number_kind!(number, N => {
        let started = Instant::now();
        let prepared = prepare_host::<N>(scene).map_err(anyhow::Error::new)?;
        let preprocess = started.elapsed();
        let mut report = ProgressReport::new(height, progress.unwrap_or(""));
        report.enabled &= progress.is_some();
        let mut statistics = Statistics::default();
        let started = Instant::now();
        let pixels = match mode {
            Mode::Pga => {
                let mut buffer = vec![0u8; pixel_count];
                if single_threaded {
                    let frame = FrameBuffer::new(&mut buffer, width, height).expect("buffer sized to the viewport");
                    render(&prepared, Pga, Whole, &mut Progress::new(frame, &report), &mut statistics);
                } else {
                    statistics = render_in_bands(&mut buffer, width, threads, &report, |sink, rows, statistics| {
                        render(&prepared, Pga, Rows(rows), sink, statistics)
                    })?;
                }
                Pixels::Pga(buffer)
            }
            Mode::Rgb => {
                let mut buffer = vec![[0u8; 3]; pixel_count];
                if single_threaded {
                    let frame = FrameBuffer::new(&mut buffer, width, height).expect("buffer sized to the viewport");
                    render(&prepared, Rgb, Whole, &mut Progress::new(frame, &report), &mut statistics);
                } else {
                    statistics = render_in_bands(&mut buffer, width, threads, &report, |sink, rows, statistics| {
                        render(&prepared, Rgb, Rows(rows), sink, statistics)
                    })?;
                }
                Pixels::Rgb(buffer)
            }
        };
        report.finish();
        Ok(Rendered { viewport, palette: scene.palette, pixels, statistics, passes: None, preprocess, trace: started.elapsed() })
    })
}

/// Prepares and renders `scene` progressively on this thread (`microtrace::render`'s
/// `render(.., Progressive, ..)`): coarse to fine in four passes, the same image as [`render_scene`],
/// with each pass's statistics. Progress counts each row once per pass.
pub fn render_scene_progressive(scene: &HostScene, number: NumberKind, mode: Mode, progress: Option<&str>) -> anyhow::Result<Rendered> {
    let viewport = scene.viewport;
    let (width, height) = (viewport.width(), viewport.height());
    let pixel_count = usize::from(width) * usize::from(height);
    if pixel_count > 64 << 20 {
        bail!("the viewport is {width}x{height}: too large to render in memory");
    }
    with_number_kind!(number, N => {
        let started = Instant::now();
        let prepared = prepare_host::<N>(scene).map_err(anyhow::Error::new)?;
        let preprocess = started.elapsed();
        let mut report = ProgressReport::new(height.saturating_mul(PASSES as u16), progress.unwrap_or(""));
        report.enabled &= progress.is_some();
        let mut passes = PassStatistics::default();
        let started = Instant::now();
        let pixels = match mode {
            Mode::Pga => {
                let mut buffer = vec![0u8; pixel_count];
                let frame = FrameBuffer::new(&mut buffer, width, height).expect("buffer sized to the viewport");
                render(&prepared, Pga, Progressive, &mut Progress::new(frame, &report), &mut passes);
                Pixels::Pga(buffer)
            }
            Mode::Rgb => {
                let mut buffer = vec![[0u8; 3]; pixel_count];
                let frame = FrameBuffer::new(&mut buffer, width, height).expect("buffer sized to the viewport");
                render(&prepared, Rgb, Progressive, &mut Progress::new(frame, &report), &mut passes);
                Pixels::Rgb(buffer)
            }
        };
        report.finish();
        Ok(Rendered { viewport, palette: scene.palette, pixels, statistics: passes.total(), passes: Some(passes), preprocess, trace: started.elapsed() })
    })
}
