#pragma once
// One rank's block of the model: the cells of an IJK box as a corner-point grid of their own
// (same COORD pillars and ZCORN depths, so every corner lands where the whole model puts it),
// with faces classified together with a one-cell halo around the box. The halo decides only
// whether a boundary face is interior, fault or shell; its cells are not part of the block and
// are never drawn (the neighbouring rank draws them). The block is cut from a source grid: the
// whole model, or only the box with its halo as the rank loaded it. No MPI here.
#include <cstdint>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/face_classification.h"
#include "grid/grid_box.h"
#include "grid/primary_selection.h"

namespace cutaway::distributed {

struct GridBlock {
    grid::IjkBox box;              ///< in the whole model's cell indices
    grid::GridDims whole_dims;
    grid::IjkBox source;           ///< the cells of the grid the block was cut from (whole-model indices)
    grid::CornerPointGrid grid;    ///< the box's cells only
    grid::FaceClassification classes;  ///< of grid's cells, classified with the halo

    /// Whole-model Eclipse index + 1 for a block Eclipse index + 1 (0 stays 0: no cell).
    std::uint32_t whole_id(std::uint32_t block_id) const;
    /// The box's values out of `source_values` (one per cell of the source grid).
    template <typename T>
    std::vector<T> own_values(const std::vector<T>& source_values) const {
        return grid::box_values(source_values, source.dims(), in_source());
    }
    /// The box in the source grid's cell indices.
    grid::IjkBox in_source() const;
};

/// `tolerance`: the whole model's face tolerance (grid::default_face_tolerance of `whole`), so a
/// block classifies its faces exactly as the whole model does.
GridBlock make_grid_block(const grid::CornerPointGrid& whole, const grid::IjkBox& box, double tolerance);
/// The same from `source`, the cells `source_box` of a model of `whole_dims`; `source_box` holds
/// the box's halo (grid::with_halo).
GridBlock make_grid_block(const grid::CornerPointGrid& source, const grid::IjkBox& source_box,
                          const grid::GridDims& whole_dims, const grid::IjkBox& box, double tolerance);

}  // namespace cutaway::distributed
