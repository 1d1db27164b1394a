#!/usr/bin/env bash
# Quick start (2): installs what is missing, builds the release preset, runs the whole ctest suite.
# `scripts/test.sh asan` does the same with AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
scripts/install-deps.sh
scripts/build.sh "$preset"
ctest --preset "$preset" -j"$(nproc)"
