//! MicroTrace on a real board in colour: a Raspberry Pi Pico (RP2040, Cortex-M0+, no FPU) with
//! a 240x240 ST7789 RGB565 display on SPI0 (GP18 = SCK, GP19 = MOSI, GP17 = CS, GP16 = D/C,
//! GP20 = reset, GP21 = backlight), driven by `mipidsi`. It parses the thesis's snooker scene on
//! the device, fits it to 240x240, renders it in `f32` and sends each finished row to the panel
//! as one contiguous fill (one address window a row) through the scene's look-up table to
//! RGB565: the core's `RowDisplaySink` and `LutColour`. See README.md.
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
use rp_pico::entry;
use rp_pico::hal::{self, pac, Clock};

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
    let mut timer = hal::Timer::new(pac.TIMER, &mut pac.RESETS, &clocks);
    let sio = hal::Sio::new(pac.SIO);
    let pins = rp_pico::Pins::new(pac.IO_BANK0, pac.PADS_BANK0, sio.gpio_bank0, &mut pac.RESETS);

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
    // The RP2040's pins cannot fail (their error type is `Infallible`).
    let Ok(spi) = ExclusiveDevice::new(spi, chip_select, timer);
    let Some(buffer) = cortex_m::singleton!(: [u8; 512] = [0; 512]) else { halt("SPI buffer already taken") };
    let interface = SpiInterface::new(spi, data_command, buffer);
    // Nothing to check here: SPI writes and the pins cannot fail on the RP2040 (a panel that is
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
    // The RP2040's 1 MHz timer times the render (what README.md's estimate is checked against).
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
