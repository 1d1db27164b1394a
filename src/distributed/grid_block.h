#pragma once
// One rank's block of the model: the cells of an IJK box as a corner-point grid of their own
// (same COORD pillars and ZCORN depths, so every corner lands where the whole model puts it),
// with faces classified together with a one-cell halo around the box. The halo decides only
// whether a boundary face is interior, fault or shell; its cells are not part of the block and
// are never drawn (the neighbouring rank draws them). No MPI here.
#include <cstdint>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/face_classification.h"
#include "grid/primary_selection.h"

namespace cutaway::distributed {

/// The cells of `box` (inclusive) of `whole`, without properties.
grid::CornerPointGrid extract_box(const grid::CornerPointGrid& whole, const grid::IjkBox& box);

/// One value per cell of `box` from `values` (one per cell of a grid of `dims`).
template <typename T>
std::vector<T> box_values(const std::vector<T>& values, const grid::GridDims& dims, const grid::IjkBox& box) {
    std::vector<T> out;
    out.reserve(std::size_t(box.i1 - box.i0 + 1) * std::size_t(box.j1 - box.j0 + 1) * std::size_t(box.k1 - box.k0 + 1));
    for (int k = box.k0; k <= box.k1; ++k)
        for (int j = box.j0; j <= box.j1; ++j)
            for (int i = box.i0; i <= box.i1; ++i) out.push_back(values[dims.cell_index(i, j, k)]);
    return out;
}

struct GridBlock {
    grid::IjkBox box;              ///< in the whole model's cell indices
    grid::GridDims whole_dims;
    grid::CornerPointGrid grid;    ///< the box's cells only
    grid::FaceClassification classes;  ///< of grid's cells, classified with the halo

    /// Whole-model Eclipse index + 1 for a block Eclipse index + 1 (0 stays 0: no cell).
    std::uint32_t whole_id(std::uint32_t block_id) const;
};

/// `tolerance`: the whole model's face tolerance (grid::default_face_tolerance of `whole`), so a
/// block classifies its faces exactly as the whole model does.
GridBlock make_grid_block(const grid::CornerPointGrid& whole, const grid::IjkBox& box, double tolerance);

}  // namespace cutaway::distributed
