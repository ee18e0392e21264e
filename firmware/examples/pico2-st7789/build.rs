//! Links a complete RP2350 image: puts memory.x (with the boot ROM's IMAGE_DEF block after the
//! vector table) where cortex-m-rt's link.x finds it and passes the linker scripts itself
//! (`-Tlink.x`: cortex-m-rt's vector table, sections and start-up; `-Tdefmt.x`: defmt's log
//! strings), as the Pico examples do. The tests check the ELF (tests/tests/real_boards.rs).
use std::path::PathBuf;

fn main() {
    let Some(out) = std::env::var_os("OUT_DIR").map(PathBuf::from) else {
        println!("cargo:warning=OUT_DIR is not set");
        std::process::exit(1);
    };
    if let Err(error) = std::fs::copy("memory.x", out.join("memory.x")) {
        println!("cargo:warning=cannot copy memory.x: {error}");
        std::process::exit(1);
    }
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rustc-link-arg-bins=--nmagic");
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rustc-link-arg-bins=-Tdefmt.x");
    bake(&out);
}

/// Bakes the thesis's snooker scene for the display into `OUT_DIR/scene.rs` (`microtrace::bake`):
/// the chip parses and prepares nothing.
fn bake(out: &std::path::Path) {
    let scene = "../../../scenes/snooker.mts";
    println!("cargo:rerun-if-changed={scene}");
    let description = match std::fs::read(scene).map_err(|error| error.to_string()).and_then(|text| microtrace::parser::parse::<64>(&text).map_err(|error| format!("{error}"))) {
        Ok(description) => description,
        Err(error) => fail(&format!("{scene}: {error}")),
    };
    match microtrace::bake::bake(&description, &microtrace::bake::Bake { size: (240, 240), number: microtrace::number::NumberKind::F32, f32_square_root: Some("microtrace_fpu_sqrt::VsqrtF32") }) {
        Ok(baked) => {
            if let Err(error) = std::fs::write(out.join("scene.rs"), baked) {
                fail(&format!("cannot write scene.rs: {error}"));
            }
        }
        Err(error) => fail(&format!("{scene}: {error}")),
    }
}

fn fail(message: &str) -> ! {
    println!("cargo:warning={message}");
    std::process::exit(1);
}
