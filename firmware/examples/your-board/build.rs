//! Bakes the scene into `OUT_DIR/scene.rs`: the whole of what a board of your own needs.
fn main() {
    let scene = "../../../scenes/snooker.mts";
    println!("cargo:rerun-if-changed={scene}");
    let description = microtrace::parser::parse::<64>(&std::fs::read(scene).unwrap()).unwrap_or_else(|error| panic!("{scene}:{error}"));
    let baked = microtrace::bake::bake(&description, &microtrace::bake::Bake::new(128, 64, microtrace::number::NumberKind::F32)).unwrap_or_else(|error| panic!("{scene}: {error}"));
    std::fs::write(std::path::Path::new(&std::env::var("OUT_DIR").unwrap()).join("scene.rs"), baked).unwrap();
}
