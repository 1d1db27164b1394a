#pragma once
// What a distributed frame needs from the whole model, computed from the ranks' parts of it by
// collectives, bit for bit what one process computes from the whole model: the active cells'
// bounds, the depth direction, the model frame with its outline, and the primary range of a
// --primary-fraction. Each rank holds `part`, the cells `part_box` of a model of `whole` dims;
// the parts may overlap (a block with its halo) and together cover the model. No MPI here.
#include <vector>

#include "cutaway/model_frame.h"
#include "distributed/mpi_session.h"
#include "grid/corner_point_grid.h"
#include "grid/point3.h"
#include "grid/primary_selection.h"

namespace cutaway::distributed {

struct ModelPart {
    const grid::CornerPointGrid& grid;
    grid::IjkBox box;        ///< the part's cells in whole-model indices
    grid::GridDims whole;
};

/// Collective: grid::grid_bounds of the whole model.
grid::Box3 global_bounds(const MpiSession& mpi, const ModelPart& part);

/// Collective: pipeline::make_model_frame of the whole model (`bounds`: global_bounds).
pipeline::ModelFrame global_model_frame(const MpiSession& mpi, const ModelPart& part, const grid::Box3& bounds,
                                        double z_scale);

/// Collective: min and max of the ranks' ranges (grid::active_value_range of each rank's own cells).
grid::PrimaryRange global_value_range(const MpiSession& mpi, const grid::PrimaryRange& own);

/// Collective: grid::range_for_fraction of the whole model from the values of each rank's own
/// active cells (no overlap: the block without its halo); `max`: the global active maximum.
grid::PrimaryRange global_range_for_fraction(const MpiSession& mpi, const std::vector<float>& own_active_values,
                                             double fraction, float max);

}  // namespace cutaway::distributed
