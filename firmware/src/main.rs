//! MicroTrace firmware: renders the scene chosen at build time (firmware/build.rs) on a
//! Cortex-M, shows it on the board's display if it has one, and reports to the host by
//! semihosting: `framebuffer.bin` (palette indices, rows top first, as the data of an
//! uncompressed PGA file; sent a row at a time as the render finishes each, with no framebuffer
//! in RAM: src/display.rs) and `report.txt` (statistics, peak stack). The instruction count is
//! taken by a QEMU plugin at the three markers in `measurement`: the frame (preparation plus
//! render), split at the render marker.
#![no_std]
#![no_main]

mod board;
mod decimal;
mod display;
mod fault;
mod measurement;
mod mpu;
mod ram;
mod report;
mod semihosting;
mod stack;
mod vectors;

/// The scene, baked from the `.mts` file by build.rs.
mod scene {
    include!(concat!(env!("OUT_DIR"), "/scene.rs"));
}

use cortex_m_rt::{entry, exception};
use microtrace::pixel::PixelSink;
#[cfg(any(feature = "framebuffer", feature = "progressive"))]
use microtrace::pixel::{FrameBuffer, PixelSource};
#[cfg(feature = "progressive")]
use microtrace::render::{PassStatistics, Progressive};
#[cfg(all(feature = "framebuffer", not(feature = "progressive")))]
use microtrace::render::Whole;
#[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
use microtrace::render::Streamed;
use microtrace::render::Pga;
#[cfg(not(feature = "progressive"))]
use microtrace::render::Statistics;
use microtrace::scene::Prepared;

use decimal::Decimal;
#[cfg(any(feature = "framebuffer", feature = "progressive"))]
use display::FramebufferAndDisplay;
#[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
use display::StreamedRows;
use semihosting::{print, HostFile};

/// The scene baked by build.rs (`microtrace::bake`): its own `Config`, whose objects, solids,
/// look-up table and view's tables stay in flash; what it keeps in RAM sized by it.
type PreparedScene = Prepared<scene::SceneConfig>;

#[entry]
fn main() -> ! {
    // The prepared scene (objects, acceleration structures) is static RAM, zero-initialised
    // and prepared in place: returned by value it would pass through the stack. (cortex-m-rt
    // makes an entry's `static mut` a `&'static mut`.)
    static mut SCENE: PreparedScene = PreparedScene::UNPREPARED;
    // From here on an access outside the flash, the RAM and the peripherals faults, and so does
    // the stack running off the bottom of RAM (src/fault.rs).
    mpu::protect_memory();
    #[cfg(microtrace_fault_test)]
    fault::provoke_if_asked();
    let display = <board::This as board::Board>::init();
    #[cfg(any(feature = "framebuffer", feature = "progressive"))]
    let Some(pixels) = cortex_m::singleton!(: [u8; scene::PIXEL_COUNT] = [0; scene::PIXEL_COUNT]) else {
        fail("framebuffer taken twice")
    };
    // The streamed build sends each row to the host as it is done: the file is open first.
    #[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
    let Some(file) = HostFile::create(b"framebuffer.bin\0") else { fail("cannot create framebuffer.bin") };

    // The frame is measured: preparation, the sink's set-up and the render.
    measurement::microtrace_measure_start();
    let scene = prepare(SCENE);

    #[cfg(any(feature = "framebuffer", feature = "progressive"))]
    let mut sink = {
        let Some(framebuffer) = FrameBuffer::new(pixels, scene::WIDTH, scene::HEIGHT) else { fail("framebuffer size") };
        FramebufferAndDisplay { framebuffer, display, palette: &scene.palette }
    };
    #[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
    let mut sink = StreamedRows::<_, { scene::WIDTH as usize }>::new(file, display, &scene.palette);
    let mut statistics = Passes::default();

    measurement::microtrace_measure_render();
    render(scene, &mut sink, &mut statistics);
    measurement::microtrace_measure_end();

    let (stack_peak_bytes, stack_size_bytes) = stack::peak_and_size();

    #[cfg(any(feature = "framebuffer", feature = "progressive"))]
    {
        let Some(mut file) = HostFile::create(b"framebuffer.bin\0") else { fail("cannot create framebuffer.bin") };
        if !file.write_all(sink.framebuffer.pixels()) {
            fail("cannot write framebuffer.bin");
        }
    }
    #[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
    {
        if sink.failed_writes != 0 || sink.sent_bytes != scene::PIXEL_COUNT {
            fail("cannot write framebuffer.bin");
        }
        // Closes framebuffer.bin before the report is written.
        drop(sink);
    }

    write_report(scene, &statistics, stack_peak_bytes, stack_size_bytes);

    print("microtrace: done\n");
    let captured = <board::This as board::Board>::hold_picture_for_capture();
    semihosting::exit(captured)
}

/// Writes `report.txt`, out of line: its 1 KB of text is on the stack only after the render
/// (in `main`'s frame it was part of the peak stack).
#[inline(never)]
fn write_report(scene: &PreparedScene, statistics: &Passes, stack_peak_bytes: u32, stack_size_bytes: u32) {
    let mut report = report::Report::new();
    report.name("board", scene::BOARD_NAME);
    report.name("scene", scene::SCENE_NAME);
    report.name("number", scene::NUMBER_NAME);
    report.integer("width", scene::WIDTH as u64);
    report.integer("height", scene::HEIGHT as u64);
    report.integer("objects", scene::OBJECT_COUNT as u64);
    // What the grid holds and what its storage could (a baked grid holds exactly its entries).
    report.integer("grid_entries", scene.acceleration.grid_entries() as u64);
    report.integer("grid_capacity", scene.acceleration.grid_capacity() as u64);
    report_statistics(&mut report, statistics);
    report.integer("stack_peak_bytes", stack_peak_bytes as u64);
    report.integer("stack_size_bytes", stack_size_bytes as u64);
    let Some(mut file) = HostFile::create(b"report.txt\0") else { fail("cannot create report.txt") };
    if !file.write_all(report.as_bytes()) {
        fail("cannot write report.txt");
    }
}

/// A sizing build (`cfg(microtrace_sizing)`, build.rs's `size_only`) has no scene prepared
/// ahead: firmware/src/ram.rs stops its compilation with the RAM the scene would need.
#[cfg(microtrace_sizing)]
fn prepare(_scene: &'static mut PreparedScene) -> &'static PreparedScene {
    fail("a sizing build does not render")
}

/// Out of line: preparing's temporaries are off the stack before the render's are on it.
#[cfg(not(microtrace_sizing))]
#[inline(never)]
fn prepare(scene: &'static mut PreparedScene) -> &'static PreparedScene {
    // From the scene baked at build time in the number type (build.rs): its settings copied,
    // its tables held where they are in flash.
    match scene.prepare_baked(&scene::SCENE) {
        Ok(()) => scene,
        Err(error) => {
            print("microtrace: the scene does not prepare, line ");
            print(Decimal::new(error.line as u64).as_str());
            fail("")
        }
    }
}

/// What the render counts: the statistics, and with the `progressive` feature each pass's.
#[cfg(not(feature = "progressive"))]
type Passes = Statistics;
#[cfg(feature = "progressive")]
type Passes = PassStatistics;

/// The render, out of line like `prepare`: its per-render tables (shadow culling, about 2 KB for
/// the lattice) are on the stack only while it runs, not under `prepare` as well. The streamed
/// render: each row traced into the sink's one row, then sent (src/display.rs).
#[inline(never)]
#[cfg(not(any(feature = "framebuffer", feature = "progressive")))]
fn render<S: PixelSink<u8>>(scene: &PreparedScene, sink: &mut S, statistics: &mut Passes) {
    microtrace::render::render(scene, Pga, Streamed, sink, statistics);
}

/// The framebuffer render (the `framebuffer` feature): Pixelbuffer's fill marked in the
/// framebuffer and read back, each finished row sent from it to the display.
#[inline(never)]
#[cfg(all(feature = "framebuffer", not(feature = "progressive")))]
fn render<S: PixelSink<u8> + PixelSource<u8>>(scene: &PreparedScene, sink: &mut S, statistics: &mut Passes) {
    microtrace::render::render(scene, Pga, Whole, sink, statistics);
}

/// The progressive render (the `progressive` feature): coarse to fine, each pass straight into
/// the framebuffer, and its rows sent to the display as each band of blocks is drawn.
#[inline(never)]
#[cfg(feature = "progressive")]
fn render<S: PixelSink<u8> + PixelSource<u8>>(scene: &PreparedScene, sink: &mut S, statistics: &mut Passes) {
    microtrace::render::render(scene, Pga, Progressive, sink, statistics);
}

#[cfg(not(feature = "progressive"))]
fn report_statistics(report: &mut report::Report, statistics: &Passes) {
    report.statistics(statistics);
}

#[cfg(feature = "progressive")]
fn report_statistics(report: &mut report::Report, statistics: &Passes) {
    report.statistics(&statistics.total());
    const KEYS: [&str; microtrace::render::PASSES] = ["pass1_rays_traced", "pass2_rays_traced", "pass3_rays_traced", "pass4_rays_traced"];
    for (key, pass) in KEYS.iter().zip(&statistics.passes) {
        report.integer(key, pass.rays_traced);
    }
}

/// Reports `why` and ends the run with failure.
fn fail(why: &str) -> ! {
    print("microtrace: failed: ");
    print(why);
    print("\n");
    semihosting::exit(false)
}

/// Panics end the run with failure, naming the place and the message when it is plain text
/// (formatting one would pull in `core::fmt`'s float and padding code). A normal build links
/// no panic path at all (the tests check it), so this is reached only by the fault test.
#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    print("microtrace: panic");
    if let Some(message) = info.message().as_str() {
        print(": ");
        print(message);
    }
    if let Some(location) = info.location() {
        print(" at ");
        print(location.file());
        print(":");
        print(Decimal::new(location.line() as u64).as_str());
    }
    print("\n");
    semihosting::exit(false)
}

// The HardFault handler is in src/fault.rs (assembly: it must leave the faulting stack first).

/// Any other exception or interrupt: none is enabled, so one is a bug. cortex-m-rt's default
/// would spin forever; this says which it was and fails the run.
#[exception]
unsafe fn DefaultHandler(number: i16) {
    print("microtrace: unexpected exception or interrupt, IRQ number ");
    if number < 0 {
        print("-");
    }
    print(Decimal::new(u64::from(number.unsigned_abs())).as_str());
    print("\n");
    semihosting::exit(false)
}
