//! The Pixelbuffer's fill, shown (§4.7.2): the core's own `fill_volumes` drives a sink that
//! records which pixels it marks. With Pixelbuffer on, only marked pixels get a ray; the
//! window tints them.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::SimulatorDisplay;
use microtrace::number::Number;
use microtrace::pixel::PixelSink;
use microtrace::render::fill_volumes;
use microtrace::config::Config;
use microtrace::scene::Prepared;

/// The tint of a marked pixel: the violet of the core's RGB-mode fill colour.
const TINT: Rgb888 = Rgb888::new(112, 0, 255);

/// Which pixels the fill marked, row by row from the top.
#[derive(Clone, Debug, Default)]
pub struct PixelbufferFill {
    width: u16,
    height: u16,
    marked: Vec<bool>,
}

impl PixelSink<bool> for PixelbufferFill {
    fn set_pixel(&mut self, x: u16, y: u16, value: bool) {
        if x < self.width && y < self.height {
            self.marked[usize::from(y) * usize::from(self.width) + usize::from(x)] = value;
        }
    }
}

impl PixelbufferFill {
    /// Runs the core's fill for `scene` (flood: unmarked, fill: marked), whether or not the
    /// scene has Pixelbuffer on: what the fill would mark.
    pub fn record<N: Number, C: Config<Number = N>>(scene: &Prepared<C>) -> Self {
        let (width, height) = (scene.camera.width(), scene.camera.height());
        let mut fill = Self { width, height, marked: vec![false; usize::from(width) * usize::from(height)] };
        fill_volumes(scene, &mut fill, true, false);
        fill
    }

    /// The fill of an antialiased render, recorded on its sample grid (the pixels' corners and
    /// their subdivisions, `step` samples a pixel side), as the image's `width` x `height`
    /// pixels: a pixel is marked when a sample on its square (edges included) is, i.e. when
    /// the render traces a ray for it.
    pub fn of_pixels(&self, step: u16, width: u16, height: u16) -> Self {
        let step = step.max(1);
        let mut pixels = Self { width, height, marked: vec![false; usize::from(width) * usize::from(height)] };
        for y in 0..height {
            for x in 0..width {
                let rows = y.saturating_mul(step)..=y.saturating_add(1).saturating_mul(step);
                let marked = rows.into_iter().any(|sy| (x.saturating_mul(step)..=x.saturating_add(1).saturating_mul(step)).any(|sx| self.is_marked(sx, sy)));
                pixels.set_pixel(x, y, marked);
            }
        }
        pixels
    }

    pub fn is_marked(&self, x: u16, y: u16) -> bool {
        x < self.width && y < self.height && self.marked[usize::from(y) * usize::from(self.width) + usize::from(x)]
    }

    /// How many pixels the fill marked.
    pub fn count(&self) -> usize {
        self.marked.iter().filter(|marked| **marked).count()
    }

    /// Tints the marked pixels of the image drawn at the window's top left: half the image's
    /// colour, half the fill's.
    pub fn draw_tint(&self, target: &mut SimulatorDisplay<Rgb888>) {
        let mix = |a: u8, b: u8| ((u16::from(a) + u16::from(b)) / 2) as u8;
        let pixels = (0..self.height)
            .flat_map(|y| (0..self.width).map(move |x| (x, y)))
            .filter(|&(x, y)| self.is_marked(x, y))
            .map(|(x, y)| {
                let at = Point::new(i32::from(x), i32::from(y));
                let under = target.get_pixel(at);
                Pixel(at, Rgb888::new(mix(under.r(), TINT.r()), mix(under.g(), TINT.g()), mix(under.b(), TINT.b())))
            })
            .collect::<Vec<_>>();
        let _ = target.draw_iter(pixels);
    }
}

#[cfg(test)]
mod tests {
    use microtrace::pixel::{FrameBuffer, PixelSource};
    use microtrace::render::{Pga, Statistics, Whole, render};

    use microtrace::pixel::PixelSink;

    use super::super::test_scenes::prepared;
    use super::PixelbufferFill;

    /// An antialiased fill on the corners' grid marks the pixels whose squares touch a marked
    /// sample, and the antialiased lattice's fill covers every pixel that shows an object.
    #[test]
    fn an_antialiased_fill_marks_the_pixels_of_its_samples() {
        // 2 x 1 pixels at step 2: 5 x 3 samples; sample (2, 0) is the corner both pixels share.
        let mut samples = PixelbufferFill { width: 5, height: 3, marked: vec![false; 15] };
        samples.set_pixel(2, 0, true);
        let pixels = samples.of_pixels(2, 2, 1);
        assert!(pixels.is_marked(0, 0) && pixels.is_marked(1, 0) && pixels.count() == 2);
        let mut samples = PixelbufferFill { width: 5, height: 3, marked: vec![false; 15] };
        samples.set_pixel(4, 2, true);
        let pixels = samples.of_pixels(2, 2, 1);
        assert!(!pixels.is_marked(0, 0) && pixels.is_marked(1, 0));

        let (_, scene) = prepared("lattice-antialiased");
        let antialias = scene.antialias.expect("the scene is antialiased");
        let image = scene.viewport();
        let (width, height) = (image.width(), image.height());
        let fill = PixelbufferFill::record(&*scene).of_pixels(antialias.step(), width, height);
        let mut buffer = vec![0u8; usize::from(width) * usize::from(height)];
        let mut frame = FrameBuffer::new(&mut buffer, width, height).unwrap();
        render(&*scene, Pga, Whole, &mut frame, &mut Statistics::default());
        assert!(fill.count() > 0 && fill.count() < usize::from(width) * usize::from(height), "the fill marks some pixels, not all");
        for y in 0..height {
            for x in 0..width {
                if frame.get_pixel(x, y) != Some(scene.background) {
                    assert!(fill.is_marked(x, y), "object pixel ({x}, {y}) not marked");
                }
            }
        }
    }

    /// With Pixelbuffer on, exactly the marked pixels get a primary ray, and every pixel that
    /// shows an object is marked.
    #[test]
    fn the_recorded_fill_is_what_the_render_traces() {
        for name in ["snooker", "lattice"] {
            let (_, scene) = prepared(name);
            assert!(scene.optimizations.pixelbuffer, "{name} has Pixelbuffer on");
            let fill = PixelbufferFill::record(&*scene);
            let (width, height) = (scene.camera.width(), scene.camera.height());
            let mut buffer = vec![0u8; usize::from(width) * usize::from(height)];
            let mut frame = FrameBuffer::new(&mut buffer, width, height).unwrap();
            let mut statistics = Statistics::default();
            render(&*scene, Pga, Whole, &mut frame, &mut statistics);
            assert_eq!(statistics.rays_traced, fill.count() as u64, "{name}");
            assert!(fill.count() > 0 && fill.count() < usize::from(width) * usize::from(height), "{name}: fill marks some pixels, not all");
            for y in 0..height {
                for x in 0..width {
                    if frame.get_pixel(x, y) != Some(scene.background) {
                        assert!(fill.is_marked(x, y), "{name}: object pixel ({x}, {y}) not marked");
                    }
                }
            }
        }
    }
}
