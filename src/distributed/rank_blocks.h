#pragma once
// How the model is cut into one block per rank: contiguous slabs of whole layers along one axis
// (K: horizontal slabs, the default; I or J: vertical slabs), with slab boundaries chosen so the
// ranks hold about equal numbers of active cells. No MPI here.
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/primary_selection.h"

namespace cutaway::distributed {

enum class SlabAxis { i, j, k };

/// "i", "j" or "k"; throws std::invalid_argument otherwise.
SlabAxis slab_axis_from_name(const std::string& name);
const char* slab_axis_name(SlabAxis axis);

/// `ranks` inclusive cell boxes covering the grid, in rank order along `axis`, each with at least
/// one active cell. Throws std::invalid_argument (naming `ranks` and the layers there are) when
/// there are fewer layers holding active cells along `axis` than ranks.
std::vector<grid::IjkBox> split_into_slabs(const grid::CornerPointGrid& grid, int ranks, SlabAxis axis);

}  // namespace cutaway::distributed
