#pragma once
// What `cutaway inspect` reports about a grid, computed once.
#include <cstddef>
#include <string>
#include <vector>

#include "grid/cell_geometry.h"
#include "grid/face_classification.h"

namespace cutaway::grid {

struct GridSummary {
    GridDims dims;
    std::size_t cells = 0;
    std::size_t active_cells = 0;
    FaceCounts faces;
    double face_tolerance = 0;
    double total_active_volume = 0;  ///< sum of |volume| over active cells, model units^3
    double min_active_volume = 0;
    double max_active_volume = 0;
    std::size_t pinched_cells = 0;   ///< active cells of zero thickness
    std::size_t inverted_cells = 0;  ///< active cells with a crossed pillar edge
    std::size_t overlapping_cells = 0;  ///< active cells whose top overlaps the layer above
    int depth_direction = 1;            ///< +1 depths grow with k, -1 they shrink
    Box3 bounds;                     ///< active cells
    bool zcorn_compact = false;
    std::size_t geometry_bytes = 0;
    std::size_t property_bytes = 0;
};

GridSummary summarize(const CornerPointGrid& grid);

}  // namespace cutaway::grid
