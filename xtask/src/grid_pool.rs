//! The firmware's grid pool sized by the scene (issue 9's "acceleration structures sized by
//! what the scene actually uses"): the scene is prepared here as the chip prepares it, from its
//! parts made ahead at the firmware's size and in its number type, and the entries its grid
//! holds become the build's `MICROTRACE_GRID_ENTRIES_PER_OBJECT` (core/src/optimize/grid.rs).

use microtrace::number::{Number, NumberKind};
use microtrace::optimize::ObjectBounds;
use microtrace::model::{Optimizations, SceneDescription};
use microtrace::scene::Scene;

use crate::firmware::FIRMWARE_SCENE_CAPACITY;

/// Entries per object for the pool, rounded up: the chip's grid, prepared from the same bounds
/// at `width`x`height` with `optimizations` (`scene`: the scene's own), holds at most this many
/// times its objects. Zero when the grid is off (or would overflow anyway and be switched off).
pub fn entries_per_object(
    description: &SceneDescription<FIRMWARE_SCENE_CAPACITY>,
    number: &str,
    optimizations: &str,
    (width, height): (u16, u16),
) -> Result<usize, String> {
    let mut description = description.clone();
    description.fit_to_size(width, height);
    if optimizations != "scene" {
        description.optimizations = Optimizations::from_list(optimizations).map_err(|name| format!("unknown optimization `{name}`"))?;
    }
    // The scene is large on the host (512 objects' capacity): prepared on a thread of its own.
    let entries = crate::host_render::on_a_large_stack("sizing the grid pool", || match NumberKind::from_name(number) {
        // The Cortex-M4F's f32 with `vsqrt.f32` is f32 bit for bit (both correctly rounded).
        Some(kind) => microtrace::with_number_kind!(kind, N => entries::<N>(&description)),
        None => Err(format!("unknown number type `{number}`")),
    })?;
    Ok(entries.div_ceil(description.objects.len().max(1)))
}

/// The entries of the grid prepared from the parts made ahead (`Scene::prepare_ahead`'s
/// `rebuild_from_bounds`), in `N`.
fn entries<N: Number>(description: &SceneDescription<FIRMWARE_SCENE_CAPACITY>) -> Result<usize, String> {
    let mut scene = Box::new(Scene::<N, FIRMWARE_SCENE_CAPACITY>::UNPREPARED);
    scene.prepare_in_place(description, &description.objects).map_err(|error| format!("the scene does not prepare: {error}"))?;
    let bounds: Vec<ObjectBounds<N>> = description.objects.iter().map(ObjectBounds::ahead).collect();
    let (camera, optimizations) = (scene.camera, scene.optimizations);
    scene.acceleration.rebuild_from_bounds(&camera, optimizations, &bounds);
    Ok(scene.acceleration.grid_entries())
}
