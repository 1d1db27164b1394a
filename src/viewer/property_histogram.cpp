#include "viewer/property_histogram.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cutaway::viewer {

namespace {

/// Calls `visit(value)` for every active cell whose value is finite.
template <typename Visit>
void for_each_active_finite(const grid::CornerPointGrid& grid, const std::vector<float>& values, Visit visit) {
    for (std::size_t cell = 0; cell < values.size(); ++cell)
        if (grid.active(cell) && std::isfinite(values[cell])) visit(values[cell]);
}

}  // namespace

PropertyHistogram active_histogram(const grid::CornerPointGrid& grid, const std::vector<float>& values, int bins) {
    if (values.size() != grid.cell_count())
        throw std::invalid_argument("histogram: " + std::to_string(values.size()) + " property values for " +
                                    std::to_string(grid.cell_count()) + " cells; expected one value per cell");
    if (bins < 1)
        throw std::invalid_argument("histogram: " + std::to_string(bins) + " bins; expected at least 1");

    PropertyHistogram histogram;
    bool first = true;
    for_each_active_finite(grid, values, [&](float value) {
        histogram.min = first ? value : std::min(histogram.min, value);
        histogram.max = first ? value : std::max(histogram.max, value);
        first = false;
    });
    // Double precision so that (max - min) cannot overflow for huge float ranges.
    const double span = double(histogram.max) - double(histogram.min);
    // Counted as integers: a float stops counting at 2^24 cells in one bin.
    std::vector<std::size_t> counts(std::size_t(bins), 0);
    for_each_active_finite(grid, values, [&](float value) {
        const int bin = span > 0 ? int((double(value) - double(histogram.min)) / span * bins) : 0;
        ++counts[std::size_t(std::clamp(bin, 0, bins - 1))];
        ++histogram.cells;
    });
    histogram.counts.assign(counts.begin(), counts.end());
    return histogram;
}

}  // namespace cutaway::viewer
