#pragma once
// A box of cells cut out of a corner-point grid as a grid of its own: the box's COORD pillars,
// ZCORN depths and ACTNUM flags, so every corner lands where the whole grid puts it.
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/primary_selection.h"

namespace cutaway::grid {

/// The cells of `box` (inclusive) of `whole`, without properties.
CornerPointGrid extract_box(const CornerPointGrid& whole, const IjkBox& box);

/// One value per cell of `box` from `values` (one per cell of a grid of `dims`).
template <typename T>
std::vector<T> box_values(const std::vector<T>& values, const GridDims& dims, const IjkBox& box) {
    std::vector<T> out;
    out.reserve(box.dims().cell_count());
    for (int k = box.k0; k <= box.k1; ++k)
        for (int j = box.j0; j <= box.j1; ++j)
            for (int i = box.i0; i <= box.i1; ++i) out.push_back(values[dims.cell_index(i, j, k)]);
    return out;
}

/// `box` grown by one cell on every side, within a grid of `dims`.
IjkBox with_halo(const IjkBox& box, const GridDims& dims);

}  // namespace cutaway::grid
