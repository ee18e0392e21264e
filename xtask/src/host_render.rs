//! The host's render of what a firmware build renders: the same scene, fitted to the firmware's
//! size, with the same optimizations, in the same number type, traced by the core on the host
//! (`render(.., Pga, Whole, ..)` into a `FrameBuffer`). The firmware report sets every run's
//! `framebuffer.bin` against it: the chip and the host agree byte for byte, or the report says
//! where they do not.

use std::path::Path;

use microtrace::model::{Optimizations, SceneDescription};
use microtrace::number::{Number, NumberKind};
use microtrace::pixel::FrameBuffer;
use microtrace::render::{render as render_scene, Pga, Statistics, Whole};
use microtrace::scene::Scene;

use crate::firmware::{FIRMWARE_SCENE_CAPACITY, FIRMWARE_SIZE};

/// The palette indices, rows top first (as `framebuffer.bin`), of `scene` rendered on the host
/// at the firmware's size in `number` with `optimizations` (`scene`: the scene's own).
pub fn render(scene: &Path, number: &str, optimizations: &str) -> Result<Vec<u8>, String> {
    let text = std::fs::read(scene).map_err(|error| format!("{}: {error}", scene.display()))?;
    let parsed: Result<microtrace::model::SceneDescription<FIRMWARE_SCENE_CAPACITY>, _> = microtrace::parser::parse_file(&scene.to_string_lossy(), &text);
    let mut description = parsed.map_err(|error| format!("{}: {error}", scene.display()))?;
    description.fit_to_size(FIRMWARE_SIZE.0, FIRMWARE_SIZE.1);
    if optimizations != "scene" {
        description.optimizations = Optimizations::from_list(optimizations).map_err(|name| format!("unknown optimization `{name}`"))?;
    }
    // The scene's capacity makes it large: prepared and rendered on a thread of its own.
    on_a_large_stack("the host render", || match NumberKind::from_name(number) {
        // The FPU boards' f32 with `vsqrt.f32` is f32 bit for bit (both correctly rounded).
        Some(kind) => microtrace::with_number_kind!(kind, N => pixels::<N>(&description)),
        None => Err(format!("unknown number type `{number}`")),
    })
}

/// Runs `work` on a thread with a 64 MB stack (a scene of the firmware's parse capacity, 512
/// objects, is megabytes on the host) and returns what it returns; `what` names it if the
/// thread cannot start or panics.
pub fn on_a_large_stack<T: Send>(what: &str, work: impl FnOnce() -> Result<T, String> + Send) -> Result<T, String> {
    std::thread::scope(|scope| {
        std::thread::Builder::new()
            .stack_size(64 << 20)
            .spawn_scoped(scope, work)
            .map_err(|error| format!("cannot start a thread: {error}"))?
            .join()
            .map_err(|_| format!("{what} failed"))?
    })
}

fn pixels<N: Number>(description: &SceneDescription<FIRMWARE_SCENE_CAPACITY>) -> Result<Vec<u8>, String> {
    let scene = Scene::<N, FIRMWARE_SCENE_CAPACITY>::prepare(description).map_err(|error| format!("the scene does not prepare: {error}"))?;
    let (width, height) = FIRMWARE_SIZE;
    let mut pixels = vec![0u8; usize::from(width) * usize::from(height)];
    let mut frame = FrameBuffer::new(&mut pixels, width, height).ok_or("the framebuffer's size")?;
    render_scene(&scene, Pga, Whole, &mut frame, &mut Statistics::default());
    Ok(pixels)
}
