//! `cargo fuzz run render`: see docs/fuzzing.md and `microtrace_fuzz::checks::render_input`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| microtrace_fuzz::checks::render_input(data));
