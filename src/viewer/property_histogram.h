#pragma once
// Histogram of a cell property over the active cells, drawn under the viewer's range sliders.
#include <cstddef>
#include <vector>

#include "grid/corner_point_grid.h"

namespace cutaway::viewer {

struct PropertyHistogram {
    float min = 0, max = 0;     ///< min/max of the finite values in active cells (0, 0 when there are none)
    std::vector<float> counts;  ///< one count per bin, as float for ImGui::PlotHistogram
    std::size_t cells = 0;      ///< active cells with a finite value (the sum of counts)
};

/// `values`: one per cell in Eclipse order (size must equal grid.cell_count(), else
/// std::invalid_argument naming both sizes). `bins` >= 1 (else std::invalid_argument). Inactive cells
/// and non-finite values are skipped. Bins split [min, max] evenly; a value equal to max goes in the
/// last bin, and when min == max every value goes in bin 0.
PropertyHistogram active_histogram(const grid::CornerPointGrid& grid, const std::vector<float>& values, int bins);

}  // namespace cutaway::viewer
