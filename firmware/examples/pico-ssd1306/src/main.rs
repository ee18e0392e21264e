//! MicroTrace on a real board: a Raspberry Pi Pico (RP2040, Cortex-M0+, no FPU) with an
//! SSD1306 128x64 monochrome OLED on I2C0 (GP4 = SDA, GP5 = SCL, address 0x3C). It renders the
//! thesis's snooker scene, baked at build time for the display (build.rs, `microtrace::bake`), renders it in `f32` and shows
//! each finished band of 8 rows (one SSD1306 page) in black and white by the core's adapters:
//! each look-up-table entry's luma through a tone curve, error-diffused (Floyd–Steinberg,
//! `ErrorDiffusion`, one row of errors in RAM); with the feature `ordered-dither`, the palette's
//! 16 grey levels by the 4x4 ordered dither instead. See README.md.
#![no_std]
#![no_main]

use defmt_rtt as _;
use fugit::RateExtU32;
#[cfg(not(feature = "ordered-dither"))]
use microtrace::pixel::{ErrorDiffusion, LutLuma};
use microtrace::pixel::{FrameBuffer, PixelSink, PixelSource, RowDisplaySink};
#[cfg(feature = "ordered-dither")]
use microtrace::pixel::{LutGrey, OrderedDither};
use microtrace::render::{Pga, Statistics, Whole};
use microtrace::scene::Prepared;
use panic_probe as _;
use rp_pico::entry;
use rp_pico::hal::{self, pac, Clock};
use ssd1306::mode::DisplayConfig;
use ssd1306::prelude::{DisplayRotation, DisplaySize128x64};
use ssd1306::{I2CDisplayInterface, Ssd1306};

/// The scene, baked by build.rs (`microtrace::bake`): its tables in flash, prepared in place.
mod scene {
    include!(concat!(env!("OUT_DIR"), "/scene.rs"));
}
const WIDTH: u16 = scene::WIDTH;
const HEIGHT: u16 = scene::HEIGHT;

/// Stops here with a message on the defmt log (no panic machinery for expected failures).
fn halt(message: &str) -> ! {
    defmt::error!("{=str}", message);
    loop {
        cortex_m::asm::wfi();
    }
}

#[entry]
fn main() -> ! {
    let Some(mut pac) = pac::Peripherals::take() else { halt("peripherals already taken") };
    let mut watchdog = hal::Watchdog::new(pac.WATCHDOG);
    let Ok(clocks) = hal::clocks::init_clocks_and_plls(
        rp_pico::XOSC_CRYSTAL_FREQ,
        pac.XOSC,
        pac.CLOCKS,
        pac.PLL_SYS,
        pac.PLL_USB,
        &mut pac.RESETS,
        &mut watchdog,
    ) else {
        halt("the clocks did not start")
    };
    defmt::info!("system clock {=u32} Hz", clocks.system_clock.freq().to_Hz());
    let sio = hal::Sio::new(pac.SIO);
    let pins = rp_pico::Pins::new(pac.IO_BANK0, pac.PADS_BANK0, sio.gpio_bank0, &mut pac.RESETS);
    let sda: hal::gpio::Pin<_, hal::gpio::FunctionI2C, hal::gpio::PullUp> = pins.gpio4.reconfigure();
    let scl: hal::gpio::Pin<_, hal::gpio::FunctionI2C, hal::gpio::PullUp> = pins.gpio5.reconfigure();
    let i2c = hal::I2C::i2c0(pac.I2C0, sda, scl, 400.kHz(), &mut pac.RESETS, &clocks.system_clock);

    let mut display = Ssd1306::new(I2CDisplayInterface::new(i2c), DisplaySize128x64, DisplayRotation::Rotate0)
        .into_buffered_graphics_mode();
    if display.init().is_err() {
        halt("the SSD1306 does not answer at 0x3C (wiring?)");
    }

    let Some(prepared) = cortex_m::singleton!(: Prepared<scene::SceneConfig> = Prepared::UNPREPARED) else { halt("the scene already taken") };
    if prepared.prepare_baked(&scene::SCENE).is_err() {
        halt("the scene does not prepare");
    }

    let Some(pixels) = cortex_m::singleton!(: [u8; WIDTH as usize * HEIGHT as usize] = [0; WIDTH as usize * HEIGHT as usize]) else {
        halt("framebuffer already taken")
    };
    let Some(frame) = FrameBuffer::new(pixels, WIDTH, HEIGHT) else { halt("framebuffer too small") };
    let mut sink = Pages(RowDisplaySink::new(frame, dots(display), greys(&prepared.palette)));
    let mut statistics = Statistics::default();
    defmt::info!("rendering {=u16}x{=u16}", WIDTH, HEIGHT);
    // The RP2040's 1 MHz timer times the render (what README.md's estimate is checked against).
    let timer = hal::Timer::new(pac.TIMER, &mut pac.RESETS, &clocks);
    let started = timer.get_counter();
    render(prepared, &mut sink, &mut statistics);
    let elapsed = timer.get_counter() - started;
    defmt::info!("rendered in {=u64} ms", elapsed.to_millis());
    defmt::info!("rays {=u64}, failed rows {=u16}", statistics.rays_traced, sink.0.failed_rows);
    loop {
        cortex_m::asm::wfi();
    }
}

/// The render, out of line (one symbol for the tests to find in the ELF).
#[inline(never)]
fn render<S: PixelSink<u8> + PixelSource<u8>>(scene: &Prepared<scene::SceneConfig>, sink: &mut S, statistics: &mut Statistics) {
    microtrace::render::render(scene, Pga, Whole, sink, statistics);
}

type Oled<DI> = Ssd1306<DI, DisplaySize128x64, ssd1306::mode::BufferedGraphicsMode<DisplaySize128x64>>;
type OledSink<'a, DI> = RowDisplaySink<'a, Dots<Oled<DI>>, Greys<'a>>;

/// How grey becomes black and white: error diffusion (the default), one row of errors in RAM.
#[cfg(not(feature = "ordered-dither"))]
type Dots<D> = ErrorDiffusion<D, { WIDTH as usize }>;
#[cfg(not(feature = "ordered-dither"))]
type Greys<'a> = LutLuma<'a>;
#[cfg(not(feature = "ordered-dither"))]
fn dots<D>(display: D) -> Dots<D> {
    ErrorDiffusion::new(display)
}
#[cfg(not(feature = "ordered-dither"))]
fn greys(palette: &microtrace::model::Palette) -> Greys<'_> {
    LutLuma::new(palette)
}
#[cfg(not(feature = "ordered-dither"))]
fn display_of<D>(dots: &mut Dots<D>) -> &mut D {
    dots.target_mut()
}

/// Or the 4x4 ordered dither of the 16 grey levels (feature `ordered-dither`).
#[cfg(feature = "ordered-dither")]
type Dots<D> = OrderedDither<D>;
#[cfg(feature = "ordered-dither")]
type Greys<'a> = LutGrey<'a>;
#[cfg(feature = "ordered-dither")]
fn dots<D>(display: D) -> Dots<D> {
    OrderedDither(display)
}
#[cfg(feature = "ordered-dither")]
fn greys(palette: &microtrace::model::Palette) -> Greys<'_> {
    LutGrey::new(palette)
}
#[cfg(feature = "ordered-dither")]
fn display_of<D>(dots: &mut Dots<D>) -> &mut D {
    &mut dots.0
}

/// The core's row sink, plus sending the SSD1306's buffer after every 8th row (one page):
/// the core sends each finished row to the driver's RAM copy, the driver sends pages on flush.
struct Pages<'a, DI>(OledSink<'a, DI>);

impl<DI: ssd1306::prelude::WriteOnlyDataCommand> PixelSink<u8> for Pages<'_, DI> {
    fn set_pixel(&mut self, x: u16, y: u16, value: u8) {
        self.0.set_pixel(x, y, value);
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        self.0.write_row(x, y, values);
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, value: u8) {
        self.0.fill_row(x, y, width, value);
    }

    fn row_done(&mut self, y: u16) {
        self.0.row_done(y);
        if y % 8 == 7 || y + 1 == HEIGHT {
            let flushed = display_of(&mut self.0.target).flush();
            if flushed.is_err() {
                self.0.failed_rows = self.0.failed_rows.saturating_add(1);
            }
        }
    }
}

impl<DI> PixelSource<u8> for Pages<'_, DI> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<u8> {
        self.0.get_pixel(x, y)
    }

    fn read_row(&self, x: u16, y: u16, values: &mut [u8]) {
        self.0.read_row(x, y, values)
    }
}
