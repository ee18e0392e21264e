//! The Pico's image, linked, with snooker baked for the SSD1306's 128x64 in `f32`
//! (../board_build.rs, shared by the real-board examples).
include!("../board_build.rs");

fn main() {
    link_and_bake(&microtrace::bake::Bake::new(128, 64, microtrace::number::NumberKind::F32));
}
