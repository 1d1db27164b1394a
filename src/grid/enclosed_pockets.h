#pragma once
// Pockets of inactive cells walled in by active ones. A model's shell faces include every face of
// an active cell next to an inactive one; where the inactive cells form a pocket inside the model,
// no line from outside reaches those faces without first crossing an active cell, so a view of
// the uncut model never shows them (the nearest shell surface and the farthest outer one are
// elsewhere on every ray). On scale-10m the outer surface without them has 1.28M faces against
// 1.80M shell faces alone (`cutaway inspect preset:scale-10m`; render's faces_drawn.shell_contours).
#include <vector>

#include "grid/grid_dims.h"
#include "grid/zcorn_store.h"

namespace cutaway::grid {

/// One flag per cell (Eclipse order), true for the inactive cells of an enclosed pocket: an IJK
/// 6-connected group of inactive cells none of which lies on a side of the grid and each of whose
/// six faces meets its neighbour's within `tolerance` (faces_meet: no fault throw, no gap between
/// layers). The group's boundary is then made of faces its active neighbours share exactly, a
/// closed wall. A group next to a fault or a gap may open into another group across it, so it is
/// never counted as enclosed. `active`: one flag per cell.
std::vector<bool> enclosed_inactive_cells(const ZcornStore& zcorn, const std::vector<bool>& active, double tolerance);

}  // namespace cutaway::grid
