//! The Pico 2's image (memory.x puts the boot ROM's IMAGE_DEF block after the vector table),
//! linked, with snooker baked for the ST7789's 240x240 in `f32` on the M33's FPU: its square
//! root is `vsqrt.f32` (firmware/fpu-sqrt), correctly rounded as the host's
//! (../board_build.rs, shared by the real-board examples).
include!("../board_build.rs");

fn main() {
    link_and_bake(&microtrace::bake::Bake { size: (240, 240), number: microtrace::number::NumberKind::F32, f32_square_root: Some("microtrace_fpu_sqrt::VsqrtF32") });
}
