#pragma once
// What `inspect` reports of each property so a user can choose `--range` without guessing: the
// active cells' minimum, maximum and percentiles (the colour range `render` fits is p2..p98).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid/corner_point_grid.h"

namespace cutaway::app {

/// {"min", "p2", "p25", "p50", "p75", "p98", "max", "positive"} of `values` over the active cells
/// of `grid` (the value at position round(f * (n - 1)) of the sorted values, as render's colour range; "positive": the share of active values above 0, which a
/// logarithmic scale can show). Throws std::invalid_argument naming `name` for NaN or infinity.
nlohmann::json property_statistics(const grid::CornerPointGrid& grid, const std::vector<float>& values,
                                   const std::string& name);

/// One line per property of `statistics` ({"NAME": property_statistics(...)}), aligned for a terminal.
std::string property_statistics_text(const nlohmann::json& statistics);

}  // namespace cutaway::app
