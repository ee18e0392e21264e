//! `cargo fuzz run parse`: see docs/fuzzing.md and `microtrace_fuzz::checks::parse_input`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| microtrace_fuzz::checks::parse_input(data));
