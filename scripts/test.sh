#!/usr/bin/env bash
# Runs every MicroTrace test: the core, the parser fuzzing, the command line, the optimizations'
# image invariance, the number types' hard cases, the simulator window under Xvfb, and the
# firmware under QEMU, and a short run of each fuzz target. Installs what is missing first (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

echo "== the core builds for a Cortex-M3 with no allocator" >&2
cargo build --quiet -p microtrace --target thumbv7m-none-eabi

echo "== clippy, warnings denied (the host workspace, all targets; the core as the firmware builds it)" >&2
cargo clippy --quiet --workspace --all-targets -- -D warnings
cargo clippy --quiet -p microtrace --no-default-features --features embedded-graphics,sphere -- -D warnings

echo "== clippy on the board examples (thumbv6m-none-eabi; the Pico 2's thumbv8m.main-none-eabihf; your-board, thumbv7em-none-eabihf; their own workspaces)" >&2
for example in firmware/examples/pico-ssd1306 firmware/examples/pico-st7789 firmware/examples/pico2-st7789 firmware/examples/your-board; do
  (cd "$example" && cargo clippy --quiet --release -- -D warnings)
done

echo "== clippy on the QEMU firmware (lm3s6965evb: streamed, framebuffer, progressive; mps2-an386, microbit, mps2-an505, netduinoplus2, lm3s811evb)" >&2
for features in "" "--features framebuffer" "--features progressive"; do
  (cd firmware && MICROTRACE_SCENE="$PWD/../scenes/snooker.mts" cargo clippy --quiet --release $features -- -D warnings)
done
(cd firmware && MICROTRACE_SCENE="$PWD/../scenes/snooker.mts" cargo clippy --quiet --release --no-default-features --features mps2-an386,sphere --target thumbv7em-none-eabihf -- -D warnings)
(cd firmware && MICROTRACE_SCENE="$PWD/../scenes/snooker.mts" cargo clippy --quiet --release --no-default-features --features microbit,sphere --target thumbv6m-none-eabi -- -D warnings)
(cd firmware && MICROTRACE_SCENE="$PWD/../scenes/snooker.mts" cargo clippy --quiet --release --no-default-features --features mps2-an505,sphere --target thumbv8m.main-none-eabihf -- -D warnings)
(cd firmware && MICROTRACE_SCENE="$PWD/../scenes/snooker.mts" cargo clippy --quiet --release --no-default-features --features netduinoplus2,sphere --target thumbv7em-none-eabihf -- -D warnings)
# The lm3s811evb's 8 KB hold snooker only with the grid xtask sizes for it: the lint build keeps
# a token stack reserve instead (the fit is tests/tests/firmware_qemu.rs's).
(cd firmware && MICROTRACE_SCENE="$PWD/../scenes/snooker.mts" MICROTRACE_STACK_RESERVE=256 cargo clippy --quiet --release --no-default-features --features lm3s811evb,sphere --target thumbv7m-none-eabi -- -D warnings)

echo "== the core's documentation, warnings denied (every feature, and the default ones)" >&2
RUSTDOCFLAGS="-D warnings" cargo doc --quiet -p microtrace --no-deps --all-features
RUSTDOCFLAGS="-D warnings" cargo doc --quiet -p microtrace --no-deps

echo "== the core packages as a crate (cargo package builds the packaged copy)" >&2
# --allow-dirty: a developer's work tree may have uncommitted changes; CI's clone has none.
cargo package --quiet -p microtrace --allow-dirty

echo "== all tests" >&2
cargo test --workspace

echo "== the fuzz targets, briefly (48 s in all; docs/fuzzing.md)" >&2
bash scripts/fuzz.sh ci 48
