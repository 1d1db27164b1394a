#!/usr/bin/env bash
# Builds the libFuzzer targets (clang) and runs them for N seconds in all (default 60): half on the
# GRDECL reader, a quarter each on the SEG-Y reader and on `render`'s option parser, each seeded
# with the shared data files (or tests/fuzz/seeds/) and the kept regressions. Crashes land in
# build-fuzz/crashes/; keep each one in tests/fuzz/regressions/ once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
scripts/install-deps.sh
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"$(nproc)" --target fuzz_grdecl_reader fuzz_segy_reader fuzz_render_options
data="${CUTAWAY_SHARED_DATA:-$(pwd)/../shared/data}"
mkdir -p build-fuzz/crashes

# run TARGET SECONDS MAX_LEN SEED_DIR...: a fresh corpus from the seeds, then libFuzzer.
run() {
  local target="$1" time="$2" max_len="$3"
  shift 3
  local corpus="build-fuzz/corpus/$target"
  mkdir -p "$corpus"
  for seeds in "$@"; do
    find "$seeds" -type f -size -1024k -exec cp {} "$corpus/" \;
  done
  "build-fuzz/bin/$target" "$corpus" -max_total_time="$time" -max_len="$max_len" -rss_limit_mb=2048 \
    -timeout=10 -artifact_prefix="build-fuzz/crashes/$target-" -print_final_stats=1
}

mkdir -p build-fuzz/seeds/grdecl build-fuzz/seeds/segy
find "$data/grdecl" tests/fuzz/regressions -name '*.grdecl' -exec cp {} build-fuzz/seeds/grdecl/ \;
find "$data/segy" tests/fuzz/regressions -name '*.sgy' -size -1024k -exec cp {} build-fuzz/seeds/segy/ \;
run fuzz_grdecl_reader $((seconds / 2)) 65536 build-fuzz/seeds/grdecl
run fuzz_segy_reader $((seconds / 4)) 65536 build-fuzz/seeds/segy
run fuzz_render_options $((seconds / 4)) 4096 tests/fuzz/seeds/render_options
