//! The pixel sink of the window: the same `PixelSink`/`PixelSource` path as the firmware. A
//! `FrameBuffer` keeps the pixels the renderer reads back; each row also goes to the simulator
//! display (PGA mode through the core's `DrawTargetSink`), and every few rows the window is
//! updated and its events handled so it stays responsive and can be closed mid-render.

use std::time::{Duration, Instant};

use embedded_graphics::pixelcolor::Rgb888 as EgRgb888;
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::{SimulatorDisplay, SimulatorEvent};
use microtrace::model::Rgb888;
use microtrace::pixel::{Borrowed, DrawTargetSink, FrameBuffer, LutColour, PixelSink, PixelSource, RgbColour};
use microtrace::model::Palette;

use super::window::View;

pub struct WindowSink<'a, P> {
    pub frame: FrameBuffer<'a, P>,
    pub display: &'a mut SimulatorDisplay<EgRgb888>,
    pub palette: &'a Palette,
    pub view: Option<&'a mut View>,
    last_update: Instant,
}

impl<'a, P: Copy> WindowSink<'a, P> {
    pub fn new(frame: FrameBuffer<'a, P>, display: &'a mut SimulatorDisplay<EgRgb888>, palette: &'a Palette, view: Option<&'a mut View>) -> Self {
        Self { frame, display, palette, view, last_update: Instant::now() }
    }

    fn refresh(&mut self, y: u16) {
        let Some(view) = self.view.as_deref_mut() else { return };
        let last = y + 1 == self.frame.height();
        if !last && self.last_update.elapsed() < Duration::from_millis(30) {
            return;
        }
        self.last_update = Instant::now();
        for event in view.update(self.display) {
            if let SimulatorEvent::Quit = event {
                eprintln!("microtrace: window closed during the render");
                std::process::exit(0);
            }
        }
    }
}

impl PixelSink<u8> for WindowSink<'_, u8> {
    fn set_pixel(&mut self, x: u16, y: u16, value: u8) {
        self.write_row(x, y, &[value]);
    }
    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        self.frame.write_row(x, y, values);
        DrawTargetSink { target: Borrowed(&mut *self.display), colours: LutColour::new(self.palette), offset: Point::zero() }.write_row(x, y, values);
    }
    fn row_done(&mut self, y: u16) {
        self.refresh(y);
    }
}

impl PixelSink<Rgb888> for WindowSink<'_, Rgb888> {
    fn set_pixel(&mut self, x: u16, y: u16, value: Rgb888) {
        self.write_row(x, y, &[value]);
    }
    fn write_row(&mut self, x: u16, y: u16, values: &[Rgb888]) {
        self.frame.write_row(x, y, values);
        DrawTargetSink { target: Borrowed(&mut *self.display), colours: RgbColour::new(), offset: Point::zero() }.write_row(x, y, values);
    }
    fn row_done(&mut self, y: u16) {
        self.refresh(y);
    }
}

impl<P: Copy> PixelSource<P> for WindowSink<'_, P> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<P> {
        self.frame.get_pixel(x, y)
    }
    fn read_row(&self, x: u16, y: u16, values: &mut [P]) {
        self.frame.read_row(x, y, values)
    }
}

