#pragma once
// Per column of a corner-point grid, what well placement needs: where its active cells are, how
// deep its top is and how much flow capacity (k h) it has.
#include <vector>

#include "grid/corner_point_grid.h"

namespace cutaway::generators {

struct ColumnSummary {
    int i = 0;                ///< column (0-based)
    int j = 0;
    double x = 0;             ///< mean centre of its active cells, model units (metres)
    double y = 0;
    double top_depth = 0;     ///< centre depth of its shallowest active cell, metres (z down)
    double kh = 0;            ///< sum of PERMX * NTG * thickness over its active cells, mD m
    /// kh summed over the column and its (up to 8) lateral neighbours, mD m: how much the
    /// reservoir around a well in this column carries, beyond the column itself.
    double neighbourhood_kh = 0;
    double footprint = 0;     ///< mean horizontal area of its active cells (volume / thickness), m2
    std::vector<int> layers;  ///< k of its active cells, ascending
};

/// The columns that hold at least one active cell of non-zero thickness, i fastest. `grid` has
/// depths growing with k and per-cell PERMX (mD) and NTG (fraction); throws
/// std::invalid_argument ("--deck: expected ...") when one is missing.
std::vector<ColumnSummary> active_columns(const grid::CornerPointGrid& grid);

}  // namespace cutaway::generators
