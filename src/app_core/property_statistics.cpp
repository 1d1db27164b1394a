#include "app_core/property_statistics.h"

#include <cstdio>

#include "grid/primary_selection.h"

namespace cutaway::app {

nlohmann::json property_statistics(const grid::CornerPointGrid& grid, const std::vector<float>& values,
                                   const std::string& name) {
    const grid::PrimaryRange range = grid::active_value_range(grid, values, name);
    const grid::PrimaryRange outer = grid::active_quantile_range(grid, values, name, 0.02, 0.98, false);
    const grid::PrimaryRange quartiles = grid::active_quantile_range(grid, values, name, 0.25, 0.75, false);
    const grid::PrimaryRange median = grid::active_quantile_range(grid, values, name, 0.5, 0.5, false);
    std::size_t active = 0, positive = 0;
    for (std::size_t cell = 0; cell < values.size(); ++cell)
        if (grid.active(cell)) {
            ++active;
            positive += values[cell] > 0;
        }
    return {{"min", range.min},      {"p2", outer.min},      {"p25", quartiles.min}, {"p50", median.min},
            {"p75", quartiles.max},  {"p98", outer.max},     {"max", range.max},
            {"positive", active ? double(positive) / double(active) : 0.0}};
}

std::string property_statistics_text(const nlohmann::json& statistics) {
    std::string text;
    char line[256];
    for (const auto& [name, s] : statistics.items()) {
        std::snprintf(line, sizeof line, "  %-16s min %-11.5g p2 %-11.5g p50 %-11.5g p98 %-11.5g max %.5g\n",
                      name.c_str(), s["min"].get<double>(), s["p2"].get<double>(), s["p50"].get<double>(),
                      s["p98"].get<double>(), s["max"].get<double>());
        text += line;
    }
    return text;
}

}  // namespace cutaway::app
