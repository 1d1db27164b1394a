#pragma once
// MODEL arguments: a GRDECL file, or `preset:NAME` for a synthetic model generated in memory.
#include <cstddef>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"

namespace cutaway::app {

struct LoadedModel {
    grid::CornerPointGrid grid;
    std::string description;  ///< file path or "preset:NAME (seed S)"
    double load_seconds = 0;
};

/// Loads `model` (files read onto one grid, or one preset:NAME); throws GrdeclError for bad files, std::invalid_argument for unknown presets.
/// `memory_limit_bytes` bounds what reading or generating may allocate.
LoadedModel load_model(const std::vector<std::string>& model, std::size_t memory_limit_bytes);

}  // namespace cutaway::app
