//! `cargo fuzz run decode`: see docs/fuzzing.md and `microtrace_fuzz::checks::decode_input`.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| microtrace_fuzz::checks::decode_input(data));
