//! Progress on a terminal for long renders: a sink wrapper that counts finished rows into a
//! report that every render thread shares.

use std::io::{IsTerminal, Write};
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use microtrace::pixel::{PixelSink, PixelSource};

/// One render's progress: the rows finished so far by any thread, shown on stderr now and then.
pub struct ProgressReport {
    /// Whether progress is shown (stderr is a terminal and the caller wants it).
    pub enabled: bool,
    rows: u16,
    label: String,
    started: Instant,
    rows_done: AtomicU32,
    last_shown: Mutex<Option<Instant>>,
}

impl ProgressReport {
    /// A report of `rows` rows, shown on stderr if it is a terminal.
    pub fn new(rows: u16, label: impl Into<String>) -> Self {
        Self {
            enabled: std::io::stderr().is_terminal(),
            rows,
            label: label.into(),
            started: Instant::now(),
            rows_done: AtomicU32::new(0),
            last_shown: Mutex::new(None),
        }
    }

    /// Counts one finished row (of any thread) and shows the count if it is due.
    pub fn row_done(&self) {
        if !self.enabled {
            return;
        }
        let done = self.rows_done.fetch_add(1, Ordering::Relaxed) + 1;
        // Another thread showing progress right now is enough: skip rather than wait for it.
        let Ok(mut last_shown) = self.last_shown.try_lock() else { return };
        let now = Instant::now();
        let due = last_shown.map_or(now - self.started > Duration::from_millis(300), |shown| now - shown > Duration::from_millis(200));
        if due {
            *last_shown = Some(now);
            eprint!("\r{}: row {done}/{} ({}%)", self.label, self.rows, done * 100 / u32::from(self.rows.max(1)));
            let _ = std::io::stderr().flush();
        }
    }

    /// Clears the progress line, if one was shown.
    pub fn finish(&self) {
        let shown = self.last_shown.lock().map_or(true, |last_shown| last_shown.is_some());
        if self.enabled && shown {
            eprint!("\r\x1b[K");
            let _ = std::io::stderr().flush();
        }
    }
}

/// A sink that passes everything to `inner` and reports each finished row to `report`.
pub struct Progress<'a, S> {
    pub inner: S,
    report: &'a ProgressReport,
}

impl<'a, S> Progress<'a, S> {
    pub fn new(inner: S, report: &'a ProgressReport) -> Self {
        Self { inner, report }
    }
}

impl<P: Copy, S: PixelSink<P>> PixelSink<P> for Progress<'_, S> {
    fn set_pixel(&mut self, x: u16, y: u16, value: P) {
        self.inner.set_pixel(x, y, value)
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[P]) {
        self.inner.write_row(x, y, values)
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        self.inner.fill_row(x, y, width, value)
    }

    fn mark_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        self.inner.mark_row(x, y, width, value)
    }

    fn row_done(&mut self, y: u16) {
        self.inner.row_done(y);
        self.report.row_done();
    }
}

impl<P: Copy, S: PixelSource<P>> PixelSource<P> for Progress<'_, S> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<P> {
        self.inner.get_pixel(x, y)
    }

    fn read_row(&self, x: u16, y: u16, values: &mut [P]) {
        self.inner.read_row(x, y, values)
    }
}
