//! A test double: a small fixed-size image that also counts what was done to it.

use super::{PixelSink, PixelSource};

/// A `W` x `H` image with call counters, for tests.
#[derive(Debug, Clone)]
pub struct MockSink<P, const W: usize, const H: usize> {
    pub pixels: [[P; W]; H],
    pub writes: u32,
    /// For each pixel, the number of writes so far when it was last written (0: never), so a
    /// test can tell the order in which pixels were written.
    pub last_write: [[u32; W]; H],
    pub rows_done: u32,
    /// Writes that fell outside the image.
    pub out_of_bounds: u32,
}

impl<P: Copy, const W: usize, const H: usize> MockSink<P, W, H> {
    pub fn new(fill: P) -> Self {
        Self { pixels: [[fill; W]; H], writes: 0, last_write: [[0; W]; H], rows_done: 0, out_of_bounds: 0 }
    }
}

impl<P: Copy, const W: usize, const H: usize> PixelSink<P> for MockSink<P, W, H> {
    fn set_pixel(&mut self, x: u16, y: u16, value: P) {
        self.writes += 1;
        match self.pixels.get_mut(y as usize).and_then(|row| row.get_mut(x as usize)) {
            Some(pixel) => {
                *pixel = value;
                if let Some(last) = self.last_write.get_mut(y as usize).and_then(|row| row.get_mut(x as usize)) {
                    *last = self.writes;
                }
            }
            None => self.out_of_bounds += 1,
        }
    }

    fn row_done(&mut self, _y: u16) {
        self.rows_done += 1;
    }
}

impl<P: Copy, const W: usize, const H: usize> PixelSource<P> for MockSink<P, W, H> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<P> {
        self.pixels.get(y as usize).and_then(|row| row.get(x as usize)).copied()
    }
}
