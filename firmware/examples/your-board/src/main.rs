//! MicroTrace on a board of your own (docs/your-board.md): the scene baked by build.rs, prepared
//! in place and rendered into a framebuffer, which goes to the host as `framebuffer.bin` (the
//! palette indices, rows top first) by semihosting. On a real board, the framebuffer goes to its
//! display instead (`microtrace::pixel`'s embedded-graphics adapters).
#![no_std]
#![no_main]

mod scene {
    include!(concat!(env!("OUT_DIR"), "/scene.rs"));
}

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, syscall};
use microtrace::pixel::FrameBuffer;
use microtrace::render::{render, Pga, Statistics, Whole};
use microtrace::scene::Prepared;

#[entry]
fn main() -> ! {
    // The scene and the picture in zero-initialised RAM, prepared in place.
    static mut SCENE: Prepared<scene::SceneConfig> = Prepared::UNPREPARED;
    static mut PIXELS: [u8; scene::PIXEL_COUNT] = [0; scene::PIXEL_COUNT];
    let Ok(()) = SCENE.prepare_baked(&scene::SCENE) else { exit(false) };
    let Some(mut frame) = FrameBuffer::new(PIXELS, scene::WIDTH, scene::HEIGHT) else { exit(false) };
    render(SCENE, Pga, Whole, &mut frame, &mut Statistics::default());
    exit(write_host_file(b"framebuffer.bin\0", PIXELS))
}

/// Writes `bytes` to the host file `path` (NUL-terminated): whether all of it was written.
fn write_host_file(path: &[u8], bytes: &[u8]) -> bool {
    // SAFETY: each argument block points at memory that outlives its call; SYS_OPEN's mode 5 is
    // "wb", SYS_WRITE returns the bytes *not* written.
    unsafe {
        let handle = syscall!(OPEN, path.as_ptr(), 5usize, path.len() - 1);
        if handle == usize::MAX {
            return false;
        }
        let not_written = syscall!(WRITE, handle, bytes.as_ptr(), bytes.len());
        syscall!(CLOSE, handle);
        not_written == 0
    }
}

/// Ends the QEMU run with success or failure.
fn exit(success: bool) -> ! {
    debug::exit(if success { debug::EXIT_SUCCESS } else { debug::EXIT_FAILURE });
    loop {
        cortex_m::asm::wfi();
    }
}

#[panic_handler]
fn panic(_info: &core::panic::PanicInfo) -> ! {
    exit(false)
}
