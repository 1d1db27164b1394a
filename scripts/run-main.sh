#!/usr/bin/env bash
# Quick start (1): installs what is missing, builds, and runs the main job: one cutaway frame of
# the built-in synthetic Sapphire model (208,320 cells, the paper's largest) at 1920x1080 with
# the paper's settings (about 1% primaries, 9x9 mean filter, SSAO, ray-cast borders) and the
# plain-frame baseline. Writes out/main.png and out/main.json (stage times, metrics, context).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
mkdir -p out
build/bin/cutaway render preset:sapphire --size 1920 1080 --primary-fraction 0.01 --mean-filter 9 --ssao on \
  --baseline --out out/main.png --stats out/main.json "$@"
/usr/bin/python3 - <<'PY'
import json
s = json.load(open("out/main.json"))
print("stage medians (ms, fenced wall clock):", {k: round(v, 1) for k, v in s["stages_ms"].items()})
print("baseline_ms:", round(s["baseline_ms"], 1), " total/baseline:", round(s["total_over_baseline"], 2))
print("primary_exposure:", s["primary_exposure"], " context_kept:", round(s["context_kept"], 3))
print("renderer:", s["gl_renderer"], " LP_NUM_THREADS:", s["lp_num_threads"])
PY
