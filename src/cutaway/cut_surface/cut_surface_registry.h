#pragma once
// The explicit list of cut-surface strategies. Tests and benchmarks iterate it, so a new
// strategy is one file plus one line in cut_surface_registry.cpp.
#include "cutaway/cut_surface/cut_surface_strategy.h"

namespace cutaway::pipeline {

std::vector<CutSurfaceEntry> cut_surface_strategies();

/// The entry called `name`; throws std::invalid_argument listing the known names.
CutSurfaceEntry find_cut_surface(const std::string& name);

}  // namespace cutaway::pipeline
