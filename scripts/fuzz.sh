#!/usr/bin/env bash
# Builds the libFuzzer target for the GRDECL reader (clang) and runs it for N seconds
# (default 60) with the shared GRDECL files as seed corpus. Crashes land in build-fuzz/crashes/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
scripts/install-deps.sh
scripts/build.sh fuzz
data="${CUTAWAY_SHARED_DATA:-$(pwd)/../shared/data}"
corpus=build-fuzz/corpus
mkdir -p "$corpus" build-fuzz/crashes
find "$data/grdecl" tests/fuzz/regressions -name '*.grdecl' -exec cp {} "$corpus/" \;
build-fuzz/bin/fuzz_grdecl_reader "$corpus" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 \
  -timeout=10 -artifact_prefix=build-fuzz/crashes/ -print_final_stats=1
