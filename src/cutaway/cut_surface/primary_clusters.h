#pragma once
// Primary cells merged into IJK boxes for the frustum-clusters strategy (the thesis's future
// work: one frustum per cluster of adjacent primaries instead of one per primary). CPU only, run
// once per selection.
//
// Boxes are maximal greedy boxes of primaries: in Eclipse order (i fastest), each primary not yet
// in a box starts one, grown along +i while the cells are free primaries, then along +j while the
// whole i-row is, then along +k while the whole ij-slab is. Every box holds primaries only (no
// secondary or inactive cell inside: as tight in IJK as a box can be), boxes are disjoint and
// cover every primary, and each lies within one 6-connected component of the primaries.
#include <cstdint>
#include <vector>

#include "grid/grid_dims.h"

namespace cutaway::pipeline {

struct IjkCellBox {
    int i0, j0, k0;  ///< first cell, inclusive
    int i1, j1, k1;  ///< last cell, inclusive
};

/// `primary`: one flag per Eclipse cell (dims.cell_count()). Throws std::invalid_argument on a
/// size mismatch.
std::vector<IjkCellBox> primary_boxes(const std::vector<std::uint8_t>& primary, const grid::GridDims& dims);

}  // namespace cutaway::pipeline
