#pragma once
// How the model is cut into one block per rank: contiguous slabs of whole layers along one axis
// (K: horizontal slabs, the default; I or J: vertical slabs), with slab boundaries chosen so the
// ranks hold about equal numbers of active cells. No MPI here.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/primary_selection.h"

namespace cutaway::distributed {

enum class SlabAxis { i, j, k };

/// "i", "j" or "k"; throws std::invalid_argument otherwise.
SlabAxis slab_axis_from_name(const std::string& name);
const char* slab_axis_name(SlabAxis axis);
/// Layers of a grid of `dims` along `axis`.
int layer_count(const grid::GridDims& dims, SlabAxis axis);

/// `ranks` inclusive cell boxes covering the grid, in rank order along `axis`, each with at least
/// one active cell. Throws std::invalid_argument (naming `ranks` and the layers there are) when
/// there are fewer layers holding active cells along `axis` than ranks.
std::vector<grid::IjkBox> split_into_slabs(const grid::CornerPointGrid& grid, int ranks, SlabAxis axis);
/// The same from the model's dimensions and its active cells per layer along `axis`.
std::vector<grid::IjkBox> split_into_slabs(const std::vector<std::uint64_t>& active_per_layer, const grid::GridDims& dims,
                                           int ranks, SlabAxis axis);

/// Active cells per layer along `axis` of a grid whose cells are `box` of a model of `dims`
/// (one count per layer of the whole model; 0 outside the box).
std::vector<std::uint64_t> active_per_layer(const grid::CornerPointGrid& grid, const grid::IjkBox& box,
                                            const grid::GridDims& dims, SlabAxis axis);

/// Slab `rank` of `ranks` slabs of equal layer counts along `axis`; none when there are fewer
/// layers than ranks and this rank gets none.
std::optional<grid::IjkBox> equal_slab(const grid::GridDims& dims, int ranks, int rank, SlabAxis axis);

}  // namespace cutaway::distributed
