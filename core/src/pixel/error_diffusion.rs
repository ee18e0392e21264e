//! The 1-bit path by error diffusion (Floyd and Steinberg, "An adaptive algorithm for spatial
//! grey scale", 1976): a dot is lit when its grey, plus the error its neighbours passed on,
//! reaches half; its own error (the grey it should show minus what it shows) goes on to the dot
//! on its right (7/16) and to the three below (3/16 left, 5/16 under, 1/16 right). The grey is
//! the look-up-table entry's own luma on an 8-bit scale ([`super::LutLuma`]) through [`tone`],
//! not the 16 levels of the ordered dither, so a ball's shading keeps its steps.
//!
//! Rows must come top first and each row's dots left to right, as [`super::RowDisplaySink`]
//! sends them (one `fill_contiguous` a row) to the streamed render's display: then one row of
//! errors is all the memory it takes (`W` of them, 2 bytes each, the row below's as far as the
//! row is done and this row's beyond; and two carried along the row). A row above the last one
//! starts a new frame. The arithmetic is integers: the same dots on every target.

use embedded_graphics_core::pixelcolor::{BinaryColor, Gray8, GrayColor};
use embedded_graphics_core::prelude::{Dimensions, DrawTarget, Point, PointsIter};
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;

/// The tone curve before the diffusion: the luma times 7/4, white from 146 up. On the thesis's
/// snooker the red balls' shading (luma 15 to 88) then lights 10 to 60 % of the dots, the cloth
/// (94) two thirds, and the balls' highlights (107 to 136) become white or nearly: without it
/// the balls were dark blots on the cloth (docs/simulator.md has both side by side).
pub const fn tone(luma: u8) -> u8 {
    let toned = luma as u16 * 7 / 4;
    if toned > 255 {
        255
    } else {
        toned as u8
    }
}

/// The diffusion's state: the errors passed to the row below and along the row.
#[derive(Clone, Debug)]
struct Diffusion<const W: usize> {
    /// For columns before the next dot, the error passed to the row below; from it on, the error
    /// the row above passed to this row.
    below: [i16; W],
    /// The row being drawn, and the column its next dot should be.
    row: Option<i32>,
    next_column: i32,
    /// The error for the next dot on this row (7/16), and for the row below at the next dot's
    /// column (1/16, added once that column's error from above is read).
    right: i32,
    below_right: i32,
}

impl<const W: usize> Diffusion<W> {
    fn dot(&mut self, point: Point, luma: u8) -> BinaryColor {
        if self.row != Some(point.y) {
            if self.row.is_some_and(|row| point.y < row) {
                // A new frame: nothing comes from above the top row.
                self.below = [0; W];
            }
            self.row = Some(point.y);
            self.next_column = 0;
            self.right = 0;
            self.below_right = 0;
        }
        if point.x != self.next_column {
            // Not the next dot of the row: what was carried along the row belongs elsewhere.
            self.right = 0;
            self.below_right = 0;
        }
        self.next_column = point.x.saturating_add(1);
        let column = usize::try_from(point.x).ok().filter(|column| *column < W);
        let from_above = column.and_then(|column| self.below.get(column)).map_or(0, |error| i32::from(*error));
        let value = i32::from(tone(luma)) + from_above + self.right;
        let lit = value >= 128;
        let error = value - if lit { 255 } else { 0 };
        // The four shares sum to the error exactly (the last takes the rounding).
        let (right, below_left, below) = ((error * 7).div_euclid(16), (error * 3).div_euclid(16), (error * 5).div_euclid(16));
        let below_right = error - right - below_left - below;
        if let Some(column) = column {
            if let Some(left) = column.checked_sub(1).and_then(|left| self.below.get_mut(left)) {
                *left = saturate(i32::from(*left) + below_left);
            }
            if let Some(under) = self.below.get_mut(column) {
                *under = saturate(below + self.below_right);
            }
        }
        self.right = right;
        self.below_right = below_right;
        BinaryColor::from(lit)
    }
}

fn saturate(error: i32) -> i16 {
    error.clamp(i32::from(i16::MIN), i32::from(i16::MAX)) as i16
}

/// An 8-bit grey `DrawTarget` over a black-and-white one, `W` dots wide: each dot by error
/// diffusion, in the order the dots arrive (rows top first, left to right). Contiguous fills stay
/// contiguous fills on the target.
#[derive(Clone, Debug)]
pub struct ErrorDiffusion<D, const W: usize> {
    target: D,
    diffusion: Diffusion<W>,
}

impl<D, const W: usize> ErrorDiffusion<D, W> {
    pub const fn new(target: D) -> Self {
        Self { target, diffusion: Diffusion { below: [0; W], row: None, next_column: 0, right: 0, below_right: 0 } }
    }

    /// The target, given back.
    pub fn into_inner(self) -> D {
        self.target
    }

    /// The target.
    pub fn target(&self) -> &D {
        &self.target
    }

    /// The target, to draw on it directly.
    pub fn target_mut(&mut self) -> &mut D {
        &mut self.target
    }
}

impl<D: Dimensions, const W: usize> Dimensions for ErrorDiffusion<D, W> {
    fn bounding_box(&self) -> Rectangle {
        self.target.bounding_box()
    }
}

impl<D: DrawTarget<Color = BinaryColor>, const W: usize> DrawTarget for ErrorDiffusion<D, W> {
    type Color = Gray8;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, pixels: I) -> Result<(), D::Error> {
        let Self { target, diffusion } = self;
        target.draw_iter(pixels.into_iter().map(|Pixel(point, grey)| Pixel(point, diffusion.dot(point, grey.luma()))))
    }

    fn fill_contiguous<I: IntoIterator<Item = Gray8>>(&mut self, area: &Rectangle, colors: I) -> Result<(), D::Error> {
        let Self { target, diffusion } = self;
        target.fill_contiguous(area, area.points().zip(colors).map(|(point, grey)| diffusion.dot(point, grey.luma())))
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use embedded_graphics_core::prelude::{OriginDimensions, Size};

    /// A black-and-white display in memory.
    struct Dots {
        width: u32,
        lit: Vec<bool>,
    }

    impl OriginDimensions for Dots {
        fn size(&self) -> Size {
            Size::new(self.width, self.lit.len() as u32 / self.width)
        }
    }

    impl DrawTarget for Dots {
        type Color = BinaryColor;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(&mut self, pixels: I) -> Result<(), Self::Error> {
            for Pixel(point, colour) in pixels {
                if let Some(dot) = self.lit.get_mut((point.y as u32 * self.width + point.x as u32) as usize) {
                    *dot = colour.is_on();
                }
            }
            Ok(())
        }
    }

    /// A `width` x `height` area of one grey, sent a row at a time, twice (two frames).
    fn diffused(width: u32, height: u32, grey: u8) -> (Vec<bool>, Vec<bool>) {
        let mut display = ErrorDiffusion::<_, 64>::new(Dots { width, lit: std::vec![false; (width * height) as usize] });
        let mut frames = Vec::new();
        for _ in 0..2 {
            for y in 0..height as i32 {
                let row = Rectangle::new(Point::new(0, y), Size::new(width, 1));
                let _ = display.fill_contiguous(&row, core::iter::repeat_n(Gray8::new(grey), width as usize));
            }
            frames.push(display.target().lit.clone());
        }
        (frames.remove(0), frames.remove(0))
    }

    #[test]
    fn a_flat_grey_lights_its_share_of_the_dots() {
        for luma in [0u8, 8, 30, 60, 73, 100, 145, 146, 200, 255] {
            let (first, second) = diffused(64, 32, luma);
            let share = first.iter().filter(|lit| **lit).count() as f64 / first.len() as f64;
            let wanted = f64::from(tone(luma)) / 255.0;
            assert!((share - wanted).abs() < 0.02, "luma {luma}: {share:.3} of the dots lit, tone {wanted:.3}");
            // The second frame starts afresh: the same dots.
            assert_eq!(first, second, "luma {luma}");
        }
        // Black and white stay black and white.
        assert!(diffused(64, 32, 0).0.iter().all(|lit| !lit));
        assert!(diffused(64, 32, 255).0.iter().all(|lit| *lit));
    }

    #[test]
    fn the_tone_curve_is_seven_quarters_up_to_white() {
        assert_eq!([tone(0), tone(4), tone(88), tone(94), tone(145), tone(146), tone(255)], [0, 7, 154, 164, 253, 255, 255]);
    }
}
