//! A framebuffer in memory the caller owns (a static array on a microcontroller, a `Vec` on a
//! host): no allocator needed.

use super::{PixelSink, PixelSource};

#[derive(Debug)]
pub struct FrameBuffer<'a, P> {
    pixels: &'a mut [P],
    width: u16,
    height: u16,
}

impl<'a, P: Copy> FrameBuffer<'a, P> {
    /// Wraps `pixels` as a `width` x `height` image, rows top first. Returns `None` when the
    /// slice is too small.
    pub fn new(pixels: &'a mut [P], width: u16, height: u16) -> Option<Self> {
        let needed = width as usize * height as usize;
        if pixels.len() < needed {
            return None;
        }
        Some(Self { pixels: &mut pixels[..needed], width, height })
    }

    pub fn width(&self) -> u16 {
        self.width
    }

    pub fn height(&self) -> u16 {
        self.height
    }

    /// All pixels, rows top first.
    pub fn pixels(&self) -> &[P] {
        self.pixels
    }

    pub fn row(&self, y: u16) -> &[P] {
        let start = y as usize * self.width as usize;
        &self.pixels[start..start + self.width as usize]
    }

    fn index(&self, x: u16, y: u16) -> Option<usize> {
        (x < self.width && y < self.height).then(|| y as usize * self.width as usize + x as usize)
    }
}

impl<P: Copy> PixelSink<P> for FrameBuffer<'_, P> {
    fn set_pixel(&mut self, x: u16, y: u16, value: P) {
        if let Some(pixel) = self.index(x, y).and_then(|index| self.pixels.get_mut(index)) {
            *pixel = value;
        }
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[P]) {
        if let Some(start) = self.index(x, y) {
            let count = values.len().min((self.width - x) as usize);
            if let (Some(pixels), Some(values)) = (self.pixels.get_mut(start..start + count), values.get(..count)) {
                pixels.copy_from_slice(values);
            }
        }
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: P) {
        if let Some(start) = self.index(x, y) {
            let count = usize::from(width.min(self.width - x));
            if let Some(pixels) = self.pixels.get_mut(start..start + count) {
                pixels.fill(value);
            }
        }
    }
}

impl<P: Copy> PixelSource<P> for FrameBuffer<'_, P> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<P> {
        self.index(x, y).and_then(|index| self.pixels.get(index).copied())
    }

    fn read_row(&self, x: u16, y: u16, values: &mut [P]) {
        if let Some(start) = self.index(x, y) {
            let count = values.len().min((self.width - x) as usize);
            if let (Some(values), Some(pixels)) = (values.get_mut(..count), self.pixels.get(start..start + count)) {
                values.copy_from_slice(pixels);
            }
        }
    }
}
