//! MicroTrace on a real board: a Raspberry Pi Pico (RP2040, Cortex-M0+, no FPU) with an
//! SSD1306 128x64 monochrome OLED on I2C0 (GP4 = SDA, GP5 = SCL, address 0x3C). It parses the
//! thesis's snooker scene on the device, fits it to the display, renders it in `f32` and shows
//! each band of rows as it finishes, the 16 grey levels ordered-dithered to black and white.
//! Build-only in this repository (`cargo xtask firmware-example`); see README.md for wiring.
#![no_std]
#![no_main]

use embedded_graphics::pixelcolor::{BinaryColor, Gray4, GrayColor};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use fugit::RateExtU32;
use microtrace::pixel::{FrameBuffer, GreyDrawTargetSink, PixelSink, PixelSource};
use microtrace::render::{render_pga, Statistics};
use microtrace::scene::{Scene, SceneDescription};
use panic_halt as _;
use rp_pico::entry;
use rp_pico::hal::{self, pac};
use ssd1306::mode::DisplayConfig;
use ssd1306::prelude::{DisplayRotation, DisplaySize128x64};
use ssd1306::{I2CDisplayInterface, Ssd1306};

/// The scene, parsed on the device with the same parser as the host.
const SCENE_TEXT: &[u8] = include_bytes!("../../../../scenes/snooker.mts");
/// Snooker has 21 balls.
const MAX_OBJECTS: usize = 24;
const WIDTH: u16 = 128;
const HEIGHT: u16 = 64;

#[entry]
fn main() -> ! {
    let mut pac = pac::Peripherals::take().unwrap();
    let mut watchdog = hal::Watchdog::new(pac.WATCHDOG);
    let clocks = hal::clocks::init_clocks_and_plls(
        rp_pico::XOSC_CRYSTAL_FREQ,
        pac.XOSC,
        pac.CLOCKS,
        pac.PLL_SYS,
        pac.PLL_USB,
        &mut pac.RESETS,
        &mut watchdog,
    )
    .ok()
    .unwrap();
    let sio = hal::Sio::new(pac.SIO);
    let pins = rp_pico::Pins::new(pac.IO_BANK0, pac.PADS_BANK0, sio.gpio_bank0, &mut pac.RESETS);
    let sda: hal::gpio::Pin<_, hal::gpio::FunctionI2C, hal::gpio::PullUp> = pins.gpio4.reconfigure();
    let scl: hal::gpio::Pin<_, hal::gpio::FunctionI2C, hal::gpio::PullUp> = pins.gpio5.reconfigure();
    let i2c = hal::I2C::i2c0(pac.I2C0, sda, scl, 400.kHz(), &mut pac.RESETS, &clocks.system_clock);

    let mut display = Ssd1306::new(I2CDisplayInterface::new(i2c), DisplaySize128x64, DisplayRotation::Rotate0)
        .into_buffered_graphics_mode();
    display.init().unwrap();

    let mut description: SceneDescription<MAX_OBJECTS> = microtrace::parser::parse(SCENE_TEXT).unwrap();
    description.fit_to_size(WIDTH, HEIGHT);
    let scene = Scene::<f32, MAX_OBJECTS>::prepare(&description).unwrap();

    let pixels = cortex_m::singleton!(: [u8; WIDTH as usize * HEIGHT as usize] = [0; WIDTH as usize * HEIGHT as usize]).unwrap();
    let mut sink = FramebufferAndOled {
        framebuffer: FrameBuffer::new(pixels, WIDTH, HEIGHT).unwrap(),
        oled: GreyDrawTargetSink { target: OrderedDither(display), palette: &scene.palette, offset: Point::zero() },
    };
    let mut statistics = Statistics::default();
    render_pga(&scene, &mut sink, &mut statistics);
    sink.oled.target.0.flush().unwrap();
    loop {
        cortex_m::asm::wfi();
    }
}

/// Shows 16 grey levels on a black-and-white display with a 4x4 Bayer matrix.
struct OrderedDither<D>(D);

const BAYER: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

impl<D: Dimensions> Dimensions for OrderedDither<D> {
    fn bounding_box(&self) -> Rectangle {
        self.0.bounding_box()
    }
}

impl<D: DrawTarget<Color = BinaryColor>> DrawTarget for OrderedDither<D> {
    type Color = Gray4;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<Gray4>>>(&mut self, pixels: I) -> Result<(), D::Error> {
        self.0.draw_iter(pixels.into_iter().map(|Pixel(point, grey)| {
            let threshold = BAYER[(point.y & 3) as usize][(point.x & 3) as usize];
            Pixel(point, if grey.luma() > threshold { BinaryColor::On } else { BinaryColor::Off })
        }))
    }
}

/// The render's sink: the framebuffer (read back by the Pixelbuffer optimization) and the
/// OLED, sent every 8 rows (one SSD1306 page).
struct FramebufferAndOled<'a, D> {
    framebuffer: FrameBuffer<'a, u8>,
    oled: GreyDrawTargetSink<'a, OrderedDither<D>>,
}

type Oled<DI> = Ssd1306<DI, DisplaySize128x64, ssd1306::mode::BufferedGraphicsMode<DisplaySize128x64>>;

impl<DI: ssd1306::prelude::WriteOnlyDataCommand> PixelSink<u8> for FramebufferAndOled<'_, Oled<DI>> {
    fn set_pixel(&mut self, x: u16, y: u16, value: u8) {
        self.framebuffer.set_pixel(x, y, value);
        self.oled.set_pixel(x, y, value);
    }

    fn write_row(&mut self, x: u16, y: u16, values: &[u8]) {
        self.framebuffer.write_row(x, y, values);
        self.oled.write_row(x, y, values);
    }

    fn row_done(&mut self, y: u16) {
        if y % 8 == 7 {
            let _ = self.oled.target.0.flush();
        }
    }
}

impl<D> PixelSource<u8> for FramebufferAndOled<'_, D> {
    fn get_pixel(&self, x: u16, y: u16) -> Option<u8> {
        self.framebuffer.get_pixel(x, y)
    }
}
