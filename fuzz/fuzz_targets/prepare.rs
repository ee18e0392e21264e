//! `cargo fuzz run prepare`: see docs/fuzzing.md and `microtrace_fuzz::checks::prepare_input`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| microtrace_fuzz::checks::prepare_input(data));
