//! Progress on a terminal for long renders: a sink wrapper that counts finished rows.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

use microtrace::pixel::{PixelSink, PixelSource};

pub struct Progress<S> {
    pub inner: S,
    rows: u16,
    /// Whether progress is shown (stderr is a terminal and the caller wants it).
    pub enabled: bool,
    label: String,
    started: Instant,
    last_shown: Option<Instant>,
}

impl<S> Progress<S> {
    /// Shows progress on stderr if it is a terminal.
    pub fn new(inner: S, rows: u16, label: impl Into<String>) -> Self {
        Self { inner, rows, label: label.into(), started: Instant::now(), last_shown: None, enabled: std::io::stderr().is_terminal() }
    }

    pub fn finish(&mut self) {
        if self.enabled && self.last_shown.is_some() {
            eprint!("\r\x1b[K");
            let _ = std::io::stderr().flush();
        }
    }
}

impl<P: Copy, S: PixelSink<P>> PixelSink<P> for Progress<S> {
    fn set_pixel(&mut self, x: u16, y: u16, value: P) {
        self.inner.set_pixel(x, y, value)
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[P]) {
        self.inner.write_row(x, y, values)
    }

    fn row_done(&mut self, y: u16) {
        self.inner.row_done(y);
        if !self.enabled {
            return;
        }
        let now = Instant::now();
        let due = self.last_shown.map_or(now - self.started > Duration::from_millis(300), |shown| now - shown > Duration::from_millis(200));
        if due {
            self.last_shown = Some(now);
            let done = u32::from(y) + 1;
            eprint!("\r{}: row {done}/{} ({}%)", self.label, self.rows, done * 100 / u32::from(self.rows.max(1)));
            let _ = std::io::stderr().flush();
        }
    }
}

impl<P: Copy, S: PixelSource<P>> PixelSource<P> for Progress<S> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<P> {
        self.inner.get_pixel(x, y)
    }

    fn read_row(&self, x: u16, y: u16, values: &mut [P]) {
        self.inner.read_row(x, y, values)
    }
}
