#!/usr/bin/env bash
# Quick start (1): installs what is missing, builds, and runs the main job.
# Until the renderer lands, the main job inspects the shared Reek grid with per-stage times.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
data="${CUTAWAY_SHARED_DATA:-$(pwd)/../shared/data}"
build/bin/cutaway inspect "$data/grdecl/reek/reek_sim_grid.grdecl" "$data/grdecl/reek/reek_sim_poro.grdecl" "$@"
