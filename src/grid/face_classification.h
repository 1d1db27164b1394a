#pragma once
// Face classes of active cells: interior (the active neighbour shares the 4 corners), fault (an
// active neighbour whose corners on the shared face differ beyond a tolerance), shell (no active
// neighbour: outside the grid or inactive).
#include <array>
#include <cstdint>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/point3.h"

namespace cutaway::grid {

enum class FaceClass : std::uint8_t { none = 0, interior = 1, fault = 2, shell = 3 };

/// Face order: I-, I+, J-, J+, K-, K+ (K+ is the bottom face, z down).
enum class FaceSide : std::uint8_t { i_minus = 0, i_plus, j_minus, j_plus, k_minus, k_plus };

/// The IJK neighbour across `side` of cell `at` (possibly outside the grid).
inline CellIjk across(CellIjk at, FaceSide side) {
    const int axis = int(side) / 2, step = int(side) % 2 == 1 ? 1 : -1;
    return {at.i + (axis == 0 ? step : 0), at.j + (axis == 1 ? step : 0), at.k + (axis == 2 ? step : 0)};
}

struct FaceCounts {
    std::size_t interior = 0;  ///< faces shared by two active cells, counted once
    std::size_t fault = 0;     ///< faces shared by two active cells, counted once
    std::size_t shell = 0;     ///< faces of an active cell with no active neighbour
};

/// Six classes per cell (FaceClass::none for inactive cells), cell-major.
class FaceClassification {
public:
    /// `tolerance`: largest corner depth difference still treated as a shared corner (model units).
    FaceClassification(const CornerPointGrid& grid, double tolerance);
    /// Classes given cell-major, six per cell (e.g. a block's, classified together with the cells
    /// around it: src/distributed/grid_block.h). Counted as above: each shell face, and interior
    /// and fault faces at their plus side.
    FaceClassification(std::vector<FaceClass> classes, double tolerance);

    FaceClass at(std::size_t cell, FaceSide side) const { return classes_[6 * cell + std::size_t(side)]; }
    const FaceCounts& counts() const { return counts_; }
    double tolerance() const { return tolerance_; }

private:
    std::vector<FaceClass> classes_;
    FaceCounts counts_;
    double tolerance_;
};

/// Whether the face of cell (i, j, k) on `side` meets the face across of its IJK neighbour (which
/// must lie in the grid): the 4 corner depths, on the same pillars, differ by at most `tolerance`.
bool faces_meet(const ZcornStore& zcorn, int i, int j, int k, FaceSide side, double tolerance);

/// Default tolerance: 1e-6 of the active cells' bounding-box diagonal (covers text rounding of
/// depths printed with 6-7 significant digits, far below any real fault throw).
double default_face_tolerance(const CornerPointGrid& grid);
/// The same for active cells spanning `bounds` (grid_bounds of the whole model).
double face_tolerance_for(const Box3& bounds);

}  // namespace cutaway::grid
