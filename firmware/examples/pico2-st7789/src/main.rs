//! MicroTrace on a Raspberry Pi Pico 2 in colour: the RP2350 (Cortex-M33 at 150 MHz with a
//! single-precision FPU) with a 240x240 ST7789 RGB565 display on SPI0, wired as for the Pico
//! example (GP18 = SCK, GP19 = MOSI, GP17 = CS, GP16 = D/C, GP20 = reset, GP21 = backlight; the
//! Pico 2 has the Pico's pinout), driven by `mipidsi`. It parses the thesis's snooker scene on
//! the device, fits it to 240x240, renders it in `f32` on the FPU (its `vsqrt.f32` too:
//! `microtrace_fpu_sqrt`) and sends each finished row to
//! the panel as one contiguous fill through the scene's look-up table to RGB565: the core's
//! `RowDisplaySink` and `LutColour`. See README.md.
#![no_std]
#![no_main]

use defmt_rtt as _;
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_hal::digital::OutputPin;
use embedded_hal_bus::spi::ExclusiveDevice;
use fugit::RateExtU32;
use microtrace::pixel::{FrameBuffer, LutColour, PixelSink, PixelSource, RowDisplaySink};
use microtrace::render::{Pga, Statistics, Whole};
use microtrace::scene::Prepared;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ST7789;
use mipidsi::options::ColorInversion;
use mipidsi::Builder;
use panic_probe as _;
use rp235x_hal::{self as hal, pac, Clock};

/// What the RP2350's boot ROM looks for in the first 4 KB of flash (memory.x puts it after the
/// vector table): an executable image for the Arm cores, run in the Secure state (RP2350
/// datasheet, 5.9, "Metadata block details": 5.9.5.1, the minimum Arm IMAGE_DEF). Without it
/// the ROM does not boot the image.
#[link_section = ".start_block"]
#[used]
pub static IMAGE_DEF: hal::block::ImageDef = hal::block::ImageDef::secure_exe();

/// The Pico 2's crystal.
const XOSC_CRYSTAL_FREQ: u32 = 12_000_000;
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

#[hal::entry]
fn main() -> ! {
    let Some(mut pac) = pac::Peripherals::take() else { halt("peripherals already taken") };
    let mut watchdog = hal::Watchdog::new(pac.WATCHDOG);
    // The PLL set-up of rp235x-hal: the system clock at 150 MHz from the 12 MHz crystal.
    let Ok(clocks) = hal::clocks::init_clocks_and_plls(
        XOSC_CRYSTAL_FREQ,
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
    let mut timer = hal::Timer::new_timer0(pac.TIMER0, &mut pac.RESETS, &clocks);
    let sio = hal::Sio::new(pac.SIO);
    let pins = hal::gpio::Pins::new(pac.IO_BANK0, pac.PADS_BANK0, sio.gpio_bank0, &mut pac.RESETS);

    let sck = pins.gpio18.into_function::<hal::gpio::FunctionSpi>();
    let mosi = pins.gpio19.into_function::<hal::gpio::FunctionSpi>();
    let chip_select = pins.gpio17.into_push_pull_output();
    let data_command = pins.gpio16.into_push_pull_output();
    let reset = pins.gpio20.into_push_pull_output();
    let mut backlight = pins.gpio21.into_push_pull_output();
    // Mode 3 (clock idle high, sample on the rising edge): what ST7789 modules without a chip
    // select need, and what those with one accept. 32 MHz: within the ST7789's write cycle.
    let spi = hal::Spi::<_, _, _, 8>::new(pac.SPI0, (mosi, sck)).init(
        &mut pac.RESETS,
        clocks.peripheral_clock.freq(),
        32.MHz(),
        embedded_hal::spi::MODE_3,
    );
    // The RP2350's pins cannot fail (their error type is `Infallible`).
    let Ok(spi) = ExclusiveDevice::new(spi, chip_select, timer);
    let Some(buffer) = cortex_m::singleton!(: [u8; 512] = [0; 512]) else { halt("SPI buffer already taken") };
    let interface = SpiInterface::new(spi, data_command, buffer);
    // Nothing to check here: SPI writes and the pins cannot fail on the RP2350 (a panel that is
    // not wired shows nothing; the defmt log still says how long the render took).
    let Ok(mut display) = Builder::new(ST7789, interface)
        .display_size(WIDTH, HEIGHT)
        // 240x240 ST7789 modules show true colours inverted.
        .invert_colors(ColorInversion::Inverted)
        .reset_pin(reset)
        .init(&mut timer);
    let _ = display.clear(Rgb565::BLACK);
    let _ = backlight.set_high();

    let Some(prepared) = cortex_m::singleton!(: Prepared<scene::SceneConfig> = Prepared::UNPREPARED) else { halt("the scene already taken") };
    if prepared.prepare_baked(&scene::SCENE).is_err() {
        halt("the scene does not prepare");
    }

    let Some(pixels) = cortex_m::singleton!(: [u8; WIDTH as usize * HEIGHT as usize] = [0; WIDTH as usize * HEIGHT as usize]) else {
        halt("framebuffer already taken")
    };
    let Some(frame) = FrameBuffer::new(pixels, WIDTH, HEIGHT) else { halt("framebuffer too small") };
    let mut sink = RowDisplaySink::new(frame, display, LutColour::<Rgb565>::new(&prepared.palette));
    let mut statistics = Statistics::default();
    defmt::info!("rendering {=u16}x{=u16}", WIDTH, HEIGHT);
    // The RP2350's 1 MHz timer times the render (what README.md's estimate is checked against).
    let started = timer.get_counter();
    render(prepared, &mut sink, &mut statistics);
    let elapsed = timer.get_counter() - started;
    defmt::info!("rendered in {=u64} ms; rays {=u64}, failed rows {=u16}", elapsed.to_millis(), statistics.rays_traced, sink.failed_rows);
    loop {
        cortex_m::asm::wfi();
    }
}

/// The render, out of line (one symbol for the tests to find in the ELF).
#[inline(never)]
fn render<S: PixelSink<u8> + PixelSource<u8>>(scene: &Prepared<scene::SceneConfig>, sink: &mut S, statistics: &mut Statistics) {
    microtrace::render::render(scene, Pga, Whole, sink, statistics);
}
