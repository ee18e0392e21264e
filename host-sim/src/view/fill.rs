//! The Pixelbuffer's fill, shown (§4.7.2): the core's own `fill_volumes` drives a sink that
//! records which pixels it marks. With Pixelbuffer on, only marked pixels get a ray; the
//! window tints them.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::SimulatorDisplay;
use microtrace::number::Number;
use microtrace::pixel::PixelSink;
use microtrace::render::fill_volumes;
use microtrace::scene::Scene;

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
    pub fn record<N: Number, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>) -> Self {
        let (width, height) = (scene.camera.width(), scene.camera.height());
        let mut fill = Self { width, height, marked: vec![false; usize::from(width) * usize::from(height)] };
        fill_volumes(scene, &mut fill, true, false);
        fill
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
    use microtrace::render::{render_pga, Statistics};

    use super::super::test_scenes::prepared;
    use super::PixelbufferFill;

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
            render_pga(&*scene, &mut frame, &mut statistics);
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
