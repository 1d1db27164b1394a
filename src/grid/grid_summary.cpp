#include "grid/grid_summary.h"

#include <algorithm>
#include <limits>

namespace cutaway::grid {

GridSummary summarize(const CornerPointGrid& grid) {
    GridSummary s;
    s.dims = grid.dims();
    s.cells = grid.cell_count();
    s.active_cells = grid.active_count();
    s.face_tolerance = default_face_tolerance(grid);
    s.faces = FaceClassification(grid, s.face_tolerance).counts();
    s.min_active_volume = std::numeric_limits<double>::infinity();
    const GridDims& d = grid.dims();
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i) {
                if (!grid.active(d.cell_index(i, j, k))) continue;
                const CellCorners corners = cell_corners(grid, i, j, k);
                const double volume = cell_volume(corners);
                s.total_active_volume += volume;
                s.min_active_volume = std::min(s.min_active_volume, volume);
                s.max_active_volume = std::max(s.max_active_volume, volume);
                s.bounds.extend(cell_bounds(corners));
                const CellShape shape = classify_shape(grid, i, j, k, s.face_tolerance);
                s.pinched_cells += shape == CellShape::pinched;
                s.inverted_cells += shape == CellShape::inverted;
                s.overlapping_cells += overlaps_layer_above(grid, i, j, k, s.face_tolerance);
            }
    if (s.active_cells == 0) s.min_active_volume = 0;
    s.depth_direction = grid.depth_direction();
    s.zcorn_compact = grid.zcorn().is_compact();
    s.geometry_bytes = grid.geometry_bytes();
    s.property_bytes = grid.property_bytes();
    return s;
}

}  // namespace cutaway::grid
