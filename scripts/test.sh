#!/usr/bin/env bash
# Runs every MicroTrace test: the core, the parser fuzzing, the command line, the optimizations'
# image invariance, the number types' hard cases, the simulator window under Xvfb, and the
# firmware under QEMU. Installs what is missing first (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

echo "== the core builds for a Cortex-M3 with no allocator" >&2
cargo build --quiet -p microtrace --target thumbv7m-none-eabi

echo "== all tests" >&2
cargo test --workspace
