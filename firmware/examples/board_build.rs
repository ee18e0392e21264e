// What every real-board example's build.rs does, written once (each includes this file):
// links a complete image — puts memory.x where cortex-m-rt's link.x finds it and passes the
// linker scripts itself (`-Tlink.x`: cortex-m-rt's vector table, sections and start-up;
// `-Tdefmt.x`: defmt's log strings; no dependency passes them for a binary, and without
// `-Tlink.x` the ELF had nothing but `.boot2`) — and bakes the thesis's snooker scene for the
// board's display into `OUT_DIR/scene.rs` (`microtrace::bake`), so the chip parses and prepares
// nothing. The tests check the ELF (tests/tests/real_boards.rs).

/// Links the image and bakes snooker as `bake` says (the display's size, the number type).
fn link_and_bake(bake: &microtrace::bake::Bake<'_>) {
    let Some(out) = std::env::var_os("OUT_DIR").map(std::path::PathBuf::from) else { fail("OUT_DIR is not set") };
    if let Err(error) = std::fs::copy("memory.x", out.join("memory.x")) {
        fail(&format!("cannot copy memory.x: {error}"));
    }
    println!("cargo:rustc-link-search={}", out.display());
    for file in ["memory.x", "build.rs", "../board_build.rs"] {
        println!("cargo:rerun-if-changed={file}");
    }
    println!("cargo:rustc-link-arg-bins=--nmagic");
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rustc-link-arg-bins=-Tdefmt.x");
    let scene = "../../../scenes/snooker.mts";
    println!("cargo:rerun-if-changed={scene}");
    let description = match std::fs::read(scene).map_err(|error| error.to_string()).and_then(|text| microtrace::parser::parse::<64>(&text).map_err(|error| format!("{error}"))) {
        Ok(description) => description,
        Err(error) => fail(&format!("{scene}: {error}")),
    };
    match microtrace::bake::bake(&description, bake) {
        Ok(baked) => {
            if let Err(error) = std::fs::write(out.join("scene.rs"), baked) {
                fail(&format!("cannot write scene.rs: {error}"));
            }
        }
        Err(error) => fail(&format!("{scene}: {error}")),
    }
}

/// Stops the build with `message`.
fn fail(message: &str) -> ! {
    println!("cargo:warning={message}");
    std::process::exit(1);
}
