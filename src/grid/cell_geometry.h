#pragma once
// Cell geometry from the raw corner-point arrays: corners, centre, exact volume, bounds, shape.
#include <array>

#include "grid/corner_point_grid.h"

namespace cutaway::grid {

/// The 8 corners of a cell. Corner bit 0: i+1 side, bit 1: j+1 side, bit 2: bottom face
/// (the ZCORN order within a cell).
using CellCorners = std::array<Point3, 8>;

/// Point on a pillar at depth z (linear along the pillar; a pillar whose top and bottom share
/// a depth is treated as vertical through its top point).
Point3 point_on_pillar(const Pillar& pillar, double z);

CellCorners cell_corners(const CornerPointGrid& grid, int i, int j, int k);

/// Mean of the 8 corners (OPM's cell centre).
Point3 cell_centre(const CellCorners& corners);

/// Volume of the trilinear hexahedron through the 8 corners, exact: the Jacobian determinant is
/// at most quadratic in each parameter, so 2-point Gauss quadrature per axis integrates it
/// exactly. Positive for i, j, k forming a right-handed frame in (x, y, z).
double signed_volume(const CellCorners& corners);
/// |signed_volume|: the volume OPM reports.
double cell_volume(const CellCorners& corners);

Box3 cell_bounds(const CellCorners& corners);

/// Shape classes found by the loader's checks.
enum class CellShape {
    regular,
    pinched,   ///< every pillar edge has zero thickness (a pinch-out): zero volume
    inverted,  ///< some pillar edge has its bottom above its top (ZCORN crossed), in the grid's
               ///< depth direction
};

/// `tolerance`: depth difference treated as zero (model units).
CellShape classify_shape(const CornerPointGrid& grid, int i, int j, int k, double tolerance);

/// Whether some top corner of cell (i,j,k) lies above the bottom corner of cell (i,j,k-1) on the
/// same pillar (layers overlap; OPM's fixupZCORN cuts such tops). Cells of layer 0 never do.
bool overlaps_layer_above(const CornerPointGrid& grid, int i, int j, int k, double tolerance);

/// Bounding box of the cells' corners; active cells only unless `all_cells`.
Box3 grid_bounds(const CornerPointGrid& grid, bool all_cells = false);

}  // namespace cutaway::grid
