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
}
