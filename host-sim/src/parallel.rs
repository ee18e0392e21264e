//! Rendering on several threads: the image is cut into bands of [`BAND_ROWS`] rows, handed out
//! one at a time to whichever thread is free (so a slow band does not hold the others up), and
//! each thread writes its band's rows of the shared buffer only, through a [`BandSink`].
//!
//! Every pixel equals the single-threaded render's (the core's `render_*_rows` promise that);
//! the statistics are the sum over bands, whose hit and shadow caches start empty at each band.

use std::num::NonZeroUsize;
use std::ops::Range;
use std::sync::{Mutex, PoisonError};

use anyhow::{anyhow, Context};
use microtrace::pixel::{FrameBuffer, PixelSink, PixelSource};
use microtrace::render::Statistics;

use crate::progress::{Progress, ProgressReport};

/// Rows per band: small enough that the bands balance between threads, large enough that the
/// per-band restart of the caches costs next to nothing.
pub const BAND_ROWS: u16 = 8;

/// The rows `first_row..first_row + height` of a `width`-wide image, stored in a slice of the
/// whole image's buffer; it takes the whole image's row indices, as the core gives them.
pub struct BandSink<'a, P> {
    band: FrameBuffer<'a, P>,
    first_row: u16,
}

impl<'a, P: Copy> BandSink<'a, P> {
    /// A band of the whole rows in `pixels`, the first of which is image row `first_row`.
    pub fn new(pixels: &'a mut [P], width: u16, first_row: u16) -> Option<Self> {
        let height = u16::try_from(pixels.len() / usize::from(width.max(1))).ok()?;
        Some(Self { band: FrameBuffer::new(pixels, width, height)?, first_row })
    }

    /// The image rows this band holds.
    pub fn rows(&self) -> Range<u16> {
        self.first_row..self.first_row + self.band.height()
    }

    /// Row `y` of the image as a row of the band, `None` outside it (ignored, as sinks do; the
    /// core never goes outside the rows it was given, so debug builds check that).
    fn band_row(&self, y: u16) -> Option<u16> {
        let row = y.checked_sub(self.first_row).filter(|row| *row < self.band.height());
        debug_assert!(row.is_some(), "row {y} is outside the band {:?}", self.rows());
        row
    }
}

impl<P: Copy> PixelSink<P> for BandSink<'_, P> {
    fn set_pixel(&mut self, x: u16, y: u16, value: P) {
        if let Some(row) = self.band_row(y) {
            self.band.set_pixel(x, row, value)
        }
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[P]) {
        if let Some(row) = self.band_row(y) {
            self.band.write_row(x, row, values)
        }
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        if let Some(row) = self.band_row(y) {
            self.band.fill_row(x, row, width, value)
        }
    }

    fn mark_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        if let Some(row) = self.band_row(y) {
            self.band.mark_row(x, row, width, value)
        }
    }
}

impl<P: Copy> PixelSource<P> for BandSink<'_, P> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<P> {
        self.band.get_pixel(x, self.band_row(y)?)
    }

    fn read_row(&self, x: u16, y: u16, values: &mut [P]) {
        if let Some(row) = self.band_row(y) {
            self.band.read_row(x, row, values)
        }
    }
}

/// Renders the `width`-wide image in `pixels` (rows top first) on up to `threads` threads:
/// `render_band` renders the given image rows into the sink and adds to the statistics.
/// Returns the statistics summed over all bands.
pub fn render_in_bands<P, F>(
    pixels: &mut [P],
    width: u16,
    threads: NonZeroUsize,
    progress: &ProgressReport,
    render_band: F,
) -> anyhow::Result<Statistics>
where
    P: Copy + Send,
    F: Fn(&mut Progress<BandSink<P>>, Range<u16>, &mut Statistics) + Sync,
{
    let band_length = usize::from(width) * usize::from(BAND_ROWS);
    if band_length == 0 {
        return Ok(Statistics::default());
    }
    let band_count = pixels.len().div_ceil(band_length);
    // The next band to render, for whichever thread asks first; the lock is held only to take one.
    let bands = Mutex::new(pixels.chunks_mut(band_length).enumerate());
    // (A panic elsewhere cannot leave the iterator half-advanced, so a poisoned lock is usable.)
    let next_band = || bands.lock().unwrap_or_else(PoisonError::into_inner).next();
    let render_bands = || -> anyhow::Result<Statistics> {
        let mut sum = Statistics::default();
        while let Some((index, band)) = next_band() {
            let first_row = u16::try_from(index * usize::from(BAND_ROWS)).context("the image has too many rows")?;
            let sink = BandSink::new(band, width, first_row).context("a band is not a whole number of rows")?;
            let rows = sink.rows();
            let mut sink = Progress::new(sink, progress);
            let mut statistics = Statistics::default();
            render_band(&mut sink, rows, &mut statistics);
            sum.add(&statistics);
        }
        Ok(sum)
    };
    // No more threads than bands; this thread renders too, beside the helpers it starts.
    let helpers = threads.get().min(band_count).saturating_sub(1);
    std::thread::scope(|scope| {
        let mut started = Vec::with_capacity(helpers);
        for number in 1..=helpers {
            let helper = std::thread::Builder::new()
                .name(format!("render-{number}"))
                .spawn_scoped(scope, render_bands)
                .with_context(|| format!("cannot start render thread {number} of {}", helpers + 1));
            match helper {
                Ok(helper) => started.push(helper),
                Err(error) => {
                    // Take the bands left, so the started threads stop soon, then report why.
                    while next_band().is_some() {}
                    return Err(error);
                }
            }
        }
        let mut total = render_bands()?;
        for helper in started {
            let statistics = helper.join().map_err(|_| anyhow!("a render thread panicked"))??;
            total.add(&statistics);
        }
        Ok(total)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_band_sink_stores_image_rows_in_its_own_rows_only() {
        let mut pixels = vec![0u8; 4 * 3];
        let mut sink = BandSink::new(&mut pixels, 4, 10).unwrap();
        assert_eq!(sink.rows(), 10..13);
        sink.set_pixel(1, 10, 7);
        sink.write_row(0, 12, &[1, 2, 3, 4, 5]);
        sink.fill_row(2, 11, 9, 9);
        assert_eq!(sink.get_pixel(1, 10), Some(7));
        let mut row = [0u8; 4];
        sink.read_row(0, 11, &mut row);
        assert_eq!(row, [0, 0, 9, 9]);
        assert_eq!(pixels, [0, 7, 0, 0, 0, 0, 9, 9, 1, 2, 3, 4]);
    }

    #[test]
    fn every_band_is_rendered_once_with_its_own_rows() {
        let (width, height) = (5u16, 21u16);
        let mut pixels = vec![0u16; usize::from(width) * usize::from(height)];
        let report = ProgressReport::new(height, "");
        let statistics = render_in_bands(&mut pixels, width, NonZeroUsize::new(3).unwrap(), &report, |sink, rows, statistics| {
            for row in rows {
                for column in 0..width {
                    sink.set_pixel(column, row, row * 100 + column);
                }
                statistics.pixels += u64::from(width);
            }
        })
        .unwrap();
        assert_eq!(statistics.pixels, u64::from(width) * u64::from(height));
        let expected: Vec<u16> = (0..height).flat_map(|row| (0..width).map(move |column| row * 100 + column)).collect();
        assert_eq!(pixels, expected);
    }
}
