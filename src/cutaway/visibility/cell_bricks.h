#pragma once
// Active cells grouped into IJK bricks for per-frame culling (SPEC.md section 6): a brick is a
// block of at most brick_side^3 cells; the GPU tests the brick's box first, then its cells.
#include <cstdint>
#include <functional>
#include <vector>

#include "cutaway/model_frame.h"
#include "grid/corner_point_grid.h"

namespace cutaway::pipeline {

/// Cells per brick along I, J and K (a brick is one 64-invocation workgroup).
inline constexpr int brick_side = 4;

struct CellBricks {
    /// Compact (active) cell indices, brick by brick.
    std::vector<std::uint32_t> cells;
    /// brick_count + 1 offsets into `cells`: brick b holds cells[begin[b] .. begin[b+1]).
    std::vector<std::uint32_t> begin;
    /// Per brick: render-space min (xyz, w 0) then max (xyz, w 0) of its cells' corners, widened
    /// by a relative 1e-5 of the model size so float rounding on the GPU stays inside.
    std::vector<float> boxes;
    std::size_t brick_count() const { return begin.empty() ? 0 : begin.size() - 1; }
};

/// Cells by compact index: an active cell's rank among the active cells in Eclipse order, as in
/// GridLayout (counted from ACTNUM, ActiveCellRank: no table of 4 bytes per cell).
/// `corners_read` (if set) is called once the boxes are built, before the cell lists are: the last
/// read of the grid's corner depths, which may be released from there.
CellBricks build_cell_bricks(const grid::CornerPointGrid& grid, const ModelFrame& frame,
                             const std::function<void()>& corners_read = {});

}  // namespace cutaway::pipeline
