#!/usr/bin/env bash
# The main job: render the thesis's snooker scene. Opens the simulator window when a display
# is available; otherwise writes snooker.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cargo build --quiet --release -p microtrace-sim
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec target/release/microtrace view scenes/snooker.mts "$@"
else
  target/release/microtrace render scenes/snooker.mts --out snooker.png --stats "$@"
  echo "no display: wrote snooker.png" >&2
fi
