#!/usr/bin/env bash
# Runs every MicroTrace test: the core, the parser fuzzing, the command line, the optimizations'
# image invariance, the number types' hard cases, the simulator window under Xvfb, and the
# firmware under QEMU, and a short run of each fuzz target. Installs what is missing first (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

echo "== the core builds for a Cortex-M3 with no allocator" >&2
cargo build --quiet -p microtrace --target thumbv7m-none-eabi

echo "== all tests" >&2
cargo test --workspace

echo "== the fuzz targets, briefly (48 s in all; docs/fuzzing.md)" >&2
bash scripts/fuzz.sh ci 48
