//! The Pico's image, linked, with snooker baked for the ST7789's 240x240 in `f32`
//! (../board_build.rs, shared by the real-board examples).
include!("../board_build.rs");

fn main() {
    link_and_bake(&microtrace::bake::Bake::new(240, 240, microtrace::number::NumberKind::F32));
}
