#!/usr/bin/env bash
# MicroTrace's coverage-guided fuzzing (cargo-fuzz / libFuzzer; docs/fuzzing.md).
#
#   bash scripts/fuzz.sh ci [SECONDS]        each target in turn, SECONDS in all (default 48),
#                                            from the committed corpus, on copies (what
#                                            scripts/test.sh runs); fails on any finding
#   bash scripts/fuzz.sh run TARGET [ARGS]   one target until stopped (or libFuzzer ARGS, e.g.
#                                            -max_total_time=600), new inputs kept in fuzz/work/
#   bash scripts/fuzz.sh long UNTIL_EPOCH    the counted long run: rounds over the targets
#                                            under `nice`, one process at a time, until the
#                                            time given (seconds since 1970); each slice's
#                                            executions and coverage go to fuzz/work/counts.tsv
#   bash scripts/fuzz.sh totals              executions per target and in all, from counts.tsv
#   bash scripts/fuzz.sh coverage TARGET     line coverage of the core by the target's corpora
#   bash scripts/fuzz.sh replay TARGET FILE  runs one input (a finding) through its target
#
# Targets: parse, prepare, render, decode. Installs cargo-fuzz when it is missing. libFuzzer
# needs nightly-only compiler flags; on the stable toolchain RUSTC_BOOTSTRAP=1 allows them.
set -euo pipefail
cd "$(dirname "$0")/.."
export RUSTC_BOOTSTRAP=1
TARGETS=(parse prepare render decode)
# No sanitizer: the core forbids `unsafe`, so AddressSanitizer would only slow the search;
# debug assertions on (-a), so that an integer overflow is a finding, as in `cargo test`.
BUILD_FLAGS=(--sanitizer none --debug-assertions)
# A slower input is a finding (libFuzzer's -timeout, in seconds: the "bounded time per input").
TIMEOUT=10

# The seeds of a target: the project's own scenes for the .mts targets (libFuzzer reads the
# folder and its subfolders: the thesis scenes, scenes/hard, scenes/spd; read only, so no
# copy of them is kept), fuzz/corpus/decode for the decoders.
seeds() {
  case "$1" in
    parse | prepare | render) echo "scenes" ;;
    *) echo "fuzz/corpus/$1" ;;
  esac
}

# The .mts targets get the format's keywords as a libFuzzer dictionary.
dictionary() {
  case "$1" in
    parse | prepare | render) echo "-dict=fuzz/mts.dict" ;;
    *) echo "-dict=fuzz/decode.dict" ;;
  esac
}

need_cargo_fuzz() {
  if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "fuzz: installing cargo-fuzz" >&2
    cargo install --locked --quiet cargo-fuzz >&2
  fi
}

binary() {
  echo "fuzz/target/x86_64-unknown-linux-gnu/release/$1"
}

# One line of counts.tsv from a finished libFuzzer log: target, seconds, executions,
# coverage (edges), features, corpus size, exit status, time ended.
record() {
  local target=$1 seconds=$2 log=$3 status=$4 runs last cov ft corp
  runs=$(grep -oE '^stat::number_of_executed_units: [0-9]+' "$log" | grep -oE '[0-9]+$' || echo 0)
  last=$(grep -E '^#[0-9]+' "$log" | tail -n 1)
  cov=$(grep -oE 'cov: [0-9]+' <<<"$last" | grep -oE '[0-9]+' || echo 0)
  ft=$(grep -oE 'ft: [0-9]+' <<<"$last" | grep -oE '[0-9]+' || echo 0)
  corp=$(grep -oE 'corp: [0-9]+' <<<"$last" | grep -oE '[0-9]+' || echo 0)
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$target" "$seconds" "$runs" "$cov" "$ft" "$corp" "$status" "$(date -u +%H:%M:%S)"
}

# Executions per target and in all, from counts.tsv.
totals() {
  awk -F'\t' 'NR > 1 { runs[$1] += $3; total += $3 } END { for (t in runs) printf "%s\t%d\n", t, runs[t]; printf "total\t%d\n", total }' "$1"
}

build() {
  need_cargo_fuzz
  (cd fuzz && cargo fuzz build "${BUILD_FLAGS[@]}" >&2)
}

case "${1:-}" in
  ci)
    total=${2:-48}
    slice=$(( total / ${#TARGETS[@]} ))
    build
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    for target in "${TARGETS[@]}"; do
      mkdir -p "$scratch/$target"
      echo "== fuzz $target for ${slice}s" >&2
      # New inputs go to the scratch copy; the committed corpus and regressions are read only.
      if ! "$(binary "$target")" "$scratch/$target" "$(seeds "$target")" "fuzz/regressions/$target" \
        -max_total_time="$slice" -timeout="$TIMEOUT" -rss_limit_mb=2048 \
        "$(dictionary "$target")" -artifact_prefix="$scratch/" -print_final_stats=1 -seed=1 >"$scratch/$target.log" 2>&1; then
        tail -n 40 "$scratch/$target.log" >&2
        echo "fuzz: $target found a problem (above)" >&2
        exit 1
      fi
      grep -E '^Done [0-9]+ runs|DONE' "$scratch/$target.log" | tail -n 2 >&2
    done
    ;;
  run)
    target=${2:?a target: ${TARGETS[*]}}
    shift 2
    build
    mkdir -p "fuzz/work/$target" fuzz/artifacts
    exec "$(binary "$target")" "fuzz/work/$target" "$(seeds "$target")" "fuzz/regressions/$target" \
      -timeout="$TIMEOUT" -rss_limit_mb=2048 "$(dictionary "$target")" -artifact_prefix="fuzz/artifacts/$target-" "$@"
    ;;
  long)
    until_epoch=${2:?the end time, in seconds since 1970 (e.g. $(date -d '+1 hour' +%s))}
    counts=fuzz/work/counts.tsv
    mkdir -p fuzz/work/bin fuzz/artifacts
    [ -f "$counts" ] || printf 'target\tseconds\truns\tcov\tft\tcorpus\texit\tended\n' >"$counts"
    # Seconds per slice (FUZZ_SLICES="parse=S prepare=S render=S decode=S" to change them),
    # roughly in inverse proportion to each target's speed: decode runs ~300,000 inputs a
    # second, parse ~20,000, prepare ~1,000, render ~100-700.
    declare -A SLICE=([parse]=900 [prepare]=900 [render]=1200 [decode]=300)
    for pair in ${FUZZ_SLICES:-}; do SLICE[${pair%%=*}]=${pair#*=}; done
    while [ "$(date +%s)" -lt "$until_epoch" ]; do
      # Built and copied each round: a fix made meanwhile is in the next round, and a rebuild
      # during a slice does not change the binary under it.
      build
      for target in "${TARGETS[@]}"; do cp "$(binary "$target")" "fuzz/work/bin/$target"; mkdir -p "fuzz/work/$target"; done
      for target in "${TARGETS[@]}"; do
        left=$(( until_epoch - $(date +%s) ))
        [ "$left" -gt 5 ] || break 2
        seconds=$(( SLICE[$target] < left ? SLICE[$target] : left ))
        log="fuzz/work/$target.log"
        set +e
        nice -n 19 "fuzz/work/bin/$target" "fuzz/work/$target" "$(seeds "$target")" "fuzz/regressions/$target" \
          -max_total_time="$seconds" -timeout="$TIMEOUT" -rss_limit_mb=2048 "$(dictionary "$target")" \
          -artifact_prefix="fuzz/artifacts/$target-" -print_final_stats=1 >"$log" 2>&1
        status=$?
        set -e
        record "$target" "$seconds" "$log" "$status" >>"$counts"
        [ "$status" -eq 0 ] || cp "$log" "fuzz/artifacts/$target-$(date +%s).log"
      done
    done
    totals "$counts"
    ;;
  totals)
    totals "${2:-fuzz/work/counts.tsv}"
    ;;
  coverage)
    # Line and region coverage of the core's files by a target's corpus (the long run's
    # fuzz/work/TARGET, the committed corpus and the regressions), through llvm-cov.
    target=${2:?a target}
    need_cargo_fuzz
    # A copy of the long run's corpus: a running fuzzer removes files from it as it reduces.
    snapshot=$(mktemp -d)
    trap 'rm -rf "$snapshot"' EXIT
    [ -d "fuzz/work/$target" ] && cp -r "fuzz/work/$target/." "$snapshot/"
    (cd fuzz && nice cargo fuzz coverage --sanitizer none "$target" "$snapshot" "../$(seeds "$target")" "regressions/$target" >&2)
    llvm_cov="$(rustc --print sysroot)/lib/rustlib/x86_64-unknown-linux-gnu/bin/llvm-cov"
    "$llvm_cov" report "fuzz/target/x86_64-unknown-linux-gnu/coverage/x86_64-unknown-linux-gnu/release/$target" \
      -instr-profile="fuzz/coverage/$target/coverage.profdata" -ignore-filename-regex='/(\.cargo|rustc)/' |
      awk '/core\/src\// { sub(/^.*core\/src\//, "core/src/", $1); printf "%-40s regions %8s  lines %8s\n", $1, $4, $10; r += $2; rm += $3; l += $8; lm += $9 }
           END { printf "%-40s regions %7.2f%%  lines %7.2f%%\n", "core (all files above)", 100 * (r - rm) / r, 100 * (l - lm) / l }'
    ;;
  replay)
    target=${2:?a target}
    build
    exec "$(binary "$target")" "${3:?an input file}"
    ;;
  *)
    sed -n '2,19p' "$0" >&2
    exit 2
    ;;
esac
