#!/usr/bin/env bash
# Runs the grid benchmarks from <build>/bin and writes
#   results/grid_load/bench_grid_load.json   Google Benchmark JSON (--benchmark_out), 5 repetitions,
#                                            aggregates (median etc.) included; "cutaway_summary"
#                                            holds the median ms per load and the OPM/cutaway ratio
#   results/grid_memory/grid_memory.json     peak memory of loading a 10-million-cell box
# Both carry machine context: uname, nproc / num_cpus, git revision, date.
#
# Build first:  cmake --preset release && cmake --build build -j2 --target bench_grid_load bench_grid_memory
# Environment:  CUTAWAY_BUILD_DIR (default: build), CUTAWAY_RESULTS_DIR (default: results),
#               BENCH_REPETITIONS (default: 5), LP_NUM_THREADS (recorded in the context if set).
# Takes about 20 s on 2 cores.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CUTAWAY_BUILD_DIR:-$root/build}"
results="${CUTAWAY_RESULTS_DIR:-$root/results}"
repetitions="${BENCH_REPETITIONS:-5}"
build="$(realpath -m "$build")"
results="$(realpath -m "$results")"
bin="$build/bin"

for exe in bench_grid_load bench_grid_memory; do
  if [[ ! -x "$bin/$exe" ]]; then
    echo "run_grid_benchmarks: $bin/$exe not built;" \
         "run: cmake --build ${build#"$root"/} -j2 --target bench_grid_load bench_grid_memory" >&2
    exit 1
  fi
done

# One revision for both programs (they fall back to asking git themselves).
revision="$(git -C "$root" rev-parse HEAD 2>/dev/null || echo unknown)"
if [[ "$revision" != unknown && -n "$(git -C "$root" status --porcelain --untracked-files=no -- . ':!results' 2>/dev/null)" ]]; then
  revision="$revision-dirty"
fi
export CUTAWAY_GIT_REVISION="$revision"

echo "run_grid_benchmarks: $(uname -srm), nproc $(nproc), revision $revision, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
mkdir -p "$results/grid_load" "$results/grid_memory"

echo "== load: cutaway vs OPM on reek_sim_grid.grdecl ($repetitions repetitions)"
"$bin/bench_grid_load" \
  --benchmark_repetitions="$repetitions" \
  --benchmark_display_aggregates_only=true \
  --benchmark_out="$results/grid_load/bench_grid_load.json" \
  --benchmark_out_format=json

echo "== memory: 250x400x100 box (write and load in separate processes)"
scratch="$build/bench_scratch"
mkdir -p "$scratch"
"$bin/bench_grid_memory" --dir "$scratch" --json "$results/grid_memory/grid_memory.json"
rmdir "$scratch" 2>/dev/null || true

echo "run_grid_benchmarks: wrote $results/grid_load/bench_grid_load.json and $results/grid_memory/grid_memory.json"
