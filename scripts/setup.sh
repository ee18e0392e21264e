#!/usr/bin/env bash
# Installs what MicroTrace's builds and tests need, when it is missing: the Cortex-M rust
# targets and llvm-tools (firmware), QEMU (firmware tests), SDL2 (the simulator window),
# Xvfb (the window test without a display), flip-link (the real-board examples), cargo-fuzz
# (the fuzz targets), Node.js and the rp2040js emulator (the Pico images run in
# tests/tests/pico_emulated.rs). Safe to run again; does nothing when all is there.
set -euo pipefail

need_rustup=()
installed_targets=$(rustup target list --installed 2>/dev/null || true)
for target in thumbv7m-none-eabi thumbv7em-none-eabihf thumbv6m-none-eabi thumbv8m.main-none-eabihf; do
  grep -qx "$target" <<<"$installed_targets" || need_rustup+=("$target")
done
if [ ${#need_rustup[@]} -gt 0 ]; then
  echo "setup: adding rust targets ${need_rustup[*]}" >&2
  rustup target add "${need_rustup[@]}" >&2
fi
if ! rustup component list --installed 2>/dev/null | grep -q '^llvm-tools'; then
  echo "setup: adding the llvm-tools component" >&2
  rustup component add llvm-tools >&2
fi

# flip-link: the real-board examples' linker (firmware/examples/*/.cargo/config.toml); a small
# crate, a few seconds to build.
if ! command -v flip-link >/dev/null; then
  echo "setup: cargo install flip-link" >&2
  cargo install --locked --quiet flip-link >&2
fi

need_apt=()
command -v qemu-system-arm >/dev/null || need_apt+=(qemu-system-arm)
pkg-config --exists sdl2 2>/dev/null || need_apt+=(libsdl2-dev pkg-config)
command -v Xvfb >/dev/null || need_apt+=(xvfb)
command -v xwd >/dev/null || need_apt+=(x11-apps)
command -v node >/dev/null || need_apt+=(nodejs)
command -v npm >/dev/null || need_apt+=(npm)
if [ ${#need_apt[@]} -gt 0 ]; then
  echo "setup: installing ${need_apt[*]}" >&2
  sudo_prefix=""
  [ "$(id -u)" -eq 0 ] || sudo_prefix="sudo"
  $sudo_prefix apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive $sudo_prefix apt-get install -y -qq "${need_apt[@]}" >&2
fi

if ! cargo fuzz --version >/dev/null 2>&1; then
  echo "setup: installing cargo-fuzz" >&2
  cargo install --locked --quiet cargo-fuzz >&2
fi

# rp2040js (the RP2040 emulator, from the npm registry) at the version package-lock.json pins,
# for the Pico images' emulated runs.
rp2040="$(dirname "$0")/../tests/rp2040"
if [ ! -f "$rp2040/node_modules/rp2040js/package.json" ]; then
  echo "setup: npm ci in tests/rp2040 (rp2040js)" >&2
  (cd "$rp2040" && npm ci --no-audit --no-fund --loglevel=error >&2)
fi
