#!/usr/bin/env bash
# The desktop speed-up against the issue's baseline commit: builds the baseline in its own
# git worktree (target/bench-baseline, with its own target dir, reused from run to run) and
# the current tree, then times `microtrace render` of both thesis scenes at their own sizes in
# f32, baseline and current alternately so that a busy machine slows both alike. The current
# binary runs with --threads 1 (the baseline is single-threaded), plus one row with its
# default threads. Prints the table and writes it to docs/desktop-speed.md.
#
#   scripts/bench-desktop.sh                  # 5 rounds
#   BENCH_ROUNDS=11 scripts/bench-desktop.sh  # more rounds, steadier medians
#
# Not part of the test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

baseline_commit=d4d5a61
rounds=${BENCH_ROUNDS:-5}
if ! [[ $rounds =~ ^[1-9][0-9]*$ ]]; then
  echo "bench-desktop: BENCH_ROUNDS must be a whole number from 1 up, not '$rounds'" >&2
  exit 1
fi
baseline_dir=$root/target/bench-baseline
baseline_tree=$baseline_dir/tree
report=docs/desktop-speed.md

# The baseline's worktree: made once, and checked to be at the baseline commit.
git worktree prune
if [ ! -e "$baseline_tree/.git" ]; then
  echo "== making the baseline worktree $baseline_tree at $baseline_commit" >&2
  mkdir -p "$baseline_dir"
  git worktree add --detach "$baseline_tree" "$baseline_commit" >&2
fi
if [ "$(git -C "$baseline_tree" rev-parse HEAD)" != "$(git rev-parse "$baseline_commit^{commit}")" ]; then
  echo "bench-desktop: $baseline_tree is not at $baseline_commit; remove it (git worktree remove $baseline_tree) and rerun" >&2
  exit 1
fi

echo "== building the baseline ($baseline_commit)" >&2
(cd "$baseline_tree" && CARGO_TARGET_DIR=$baseline_dir/target cargo build --quiet --release -p microtrace-sim)
baseline_bin=$baseline_dir/target/release/microtrace
echo "== building the current tree" >&2
cargo build --quiet --release -p microtrace-sim
current_target=${CARGO_TARGET_DIR:-target}
current_bin=$current_target/release/microtrace
default_threads=$(nproc)

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Runs the command given and prints its wall time in milliseconds; its output goes to the
# scratch directory (a failure stops the script, with the command's error shown).
time_ms() {
  local started finished
  started=$(date +%s.%N)
  if ! "$@" >"$scratch/stdout" 2>"$scratch/stderr"; then
    echo "bench-desktop: failed: $*" >&2
    cat "$scratch/stderr" >&2
    exit 1
  fi
  finished=$(date +%s.%N)
  awk -v a="$started" -v b="$finished" 'BEGIN { printf "%.1f\n", (b - a) * 1000 }'
}

# The median of the numbers given, one a line on stdin.
median() {
  sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else printf "%.1f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# "fastest–slowest" of the numbers given, one a line on stdin: how noisy the median is.
spread() {
  sort -g | awk 'NR == 1 { low = $1 } { high = $1 } END { print low "–" high }'
}

ratio() {
  awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'
}

commit=$(git rev-parse --short HEAD)
git diff --quiet HEAD -- core host-sim Cargo.toml Cargo.lock || commit="$commit (with uncommitted changes)"
load=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)
table="| scene | binary | median wall time (ms) | fastest–slowest (ms) | baseline / this |
|---|---|---:|---:|---:|"
for scene in snooker lattice; do
  scene_file=scenes/$scene.mts
  baseline_times=() current_times=() threaded_times=()
  for round in $(seq "$rounds"); do
    echo "== $scene_file, round $round of $rounds" >&2
    baseline_times+=("$(time_ms "$baseline_bin" render "$scene_file" --number f32 --out "$scratch/baseline.png")")
    current_times+=("$(time_ms "$current_bin" render "$scene_file" --number f32 --threads 1 --out "$scratch/current.png")")
    threaded_times+=("$(time_ms "$current_bin" render "$scene_file" --number f32 --out "$scratch/threaded.png")")
  done
  # The speed-up means little if the images differ; say so rather than hide it.
  same="same image"
  cmp -s "$scratch/baseline.png" "$scratch/current.png" || same="IMAGE DIFFERS from the baseline's"
  cmp -s "$scratch/current.png" "$scratch/threaded.png" || same="$same; THREADED IMAGE DIFFERS"
  size=$(grep -m1 '^viewport' "$scene_file" | awk '{ printf "%dx%d", $3 - $2 + 1, $5 - $4 + 1 }')
  baseline_ms=$(printf '%s\n' "${baseline_times[@]}" | median)
  current_ms=$(printf '%s\n' "${current_times[@]}" | median)
  threaded_ms=$(printf '%s\n' "${threaded_times[@]}" | median)
  table+="
| $scene.mts ($size) | baseline $baseline_commit | $baseline_ms | $(printf '%s\n' "${baseline_times[@]}" | spread) | 1.00 |
| | current, \`--threads 1\` ($same) | $current_ms | $(printf '%s\n' "${current_times[@]}" | spread) | $(ratio "$baseline_ms" "$current_ms") |
| | current, default threads ($default_threads) | $threaded_ms | $(printf '%s\n' "${threaded_times[@]}" | spread) | $(ratio "$baseline_ms" "$threaded_ms") |"
done

printf '%s\n' "$table"
{
  echo "# Desktop speed against $baseline_commit"
  echo
  echo "Generated by \`scripts/bench-desktop.sh\`; do not edit, rerun it (\`BENCH_ROUNDS=N\` for more rounds)."
  echo
  echo "- current commit: $commit; baseline: $baseline_commit (the issue's baseline, single-threaded)"
  echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC'); host: $(uname -sm), $default_threads hardware threads, load average $load at the start"
  echo "- command: \`microtrace render scenes/SCENE.mts --number f32 --out x.png\` at the scene's own size, release build;"
  echo "  the current binary with \`--threads 1\`, and once more with its default (one thread per core)"
  echo "- $rounds rounds, baseline and current alternately; wall time of the whole process (start-up, scene"
  echo "  loading, preparation, trace, PNG writing), median of the rounds; on a shared, loaded machine these"
  echo "  renders of a tenth of a second vary a lot from run to run (see fastest–slowest): compare ratios well"
  echo "  away from 1.0 only"
  echo
  printf '%s\n' "$table"
} >"$scratch/report.md"
mv "$scratch/report.md" "$report"
echo "== wrote $report" >&2
