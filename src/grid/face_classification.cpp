#include "grid/face_classification.h"

#include <cmath>
#include <utility>

#include "grid/cell_geometry.h"

namespace cutaway::grid {

FaceClassification::FaceClassification(const CornerPointGrid& grid, double tolerance)
    : classes_(6 * grid.cell_count(), FaceClass::none), tolerance_(tolerance) {
    const GridDims& d = grid.dims();
    const ZcornStore& z = grid.zcorn();
    std::size_t shell = 0, fault = 0, interior = 0;
    // Rows of cells split over the threads: each writes only its own cells' faces.
#pragma omp parallel for collapse(2) schedule(static) reduction(+ : shell, fault, interior)
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i) {
                const std::size_t cell = d.cell_index(i, j, k);
                if (!grid.active(cell)) continue;
                for (int side = 0; side < 6; ++side) {
                    const bool plus = side % 2 == 1;
                    const CellIjk n = across({i, j, k}, FaceSide(side));
                    FaceClass face = FaceClass::shell;
                    if (d.contains(n.i, n.j, n.k) && grid.active(d.cell_index(n.i, n.j, n.k)))
                        face = faces_meet(z, i, j, k, FaceSide(side), tolerance) ? FaceClass::interior : FaceClass::fault;
                    classes_[6 * cell + std::size_t(side)] = face;
                    if (face == FaceClass::shell)
                        ++shell;
                    else if (plus)
                        ++(face == FaceClass::fault ? fault : interior);
                }
            }
    counts_.shell = shell;
    counts_.fault = fault;
    counts_.interior = interior;
}

FaceClassification::FaceClassification(std::vector<FaceClass> classes, double tolerance)
    : classes_(std::move(classes)), tolerance_(tolerance) {
    for (std::size_t face = 0; face < classes_.size(); ++face) {
        const FaceClass c = classes_[face];
        const bool plus = face % 2 == 1;
        if (c == FaceClass::shell) ++counts_.shell;
        else if (plus && c == FaceClass::fault) ++counts_.fault;
        else if (plus && c == FaceClass::interior) ++counts_.interior;
    }
}

bool faces_meet(const ZcornStore& zcorn, int i, int j, int k, FaceSide side, double tolerance) {
    const int axis = int(side) / 2;
    const bool plus = int(side) % 2 == 1;
    const CellIjk n = across({i, j, k}, side);
    // Corners on this face have the axis bit set (plus side) or clear; the neighbour's matching
    // corners sit on the same pillars with the bit flipped.
    const int bit = 1 << axis;
    for (int c = 0; c < 8; ++c) {
        if (((c & bit) != 0) != plus) continue;
        if (std::abs(zcorn.corner_depth(i, j, k, c) - zcorn.corner_depth(n.i, n.j, n.k, c ^ bit)) > tolerance) return false;
    }
    return true;
}

double default_face_tolerance(const CornerPointGrid& grid) { return face_tolerance_for(grid_bounds(grid)); }

double face_tolerance_for(const Box3& box) {
    if (box.empty()) return 1e-9;
    const double dx = box.max.x - box.min.x, dy = box.max.y - box.min.y, dz = box.max.z - box.min.z;
    return std::max(1e-6 * std::sqrt(dx * dx + dy * dy + dz * dz), 1e-9);
}

}  // namespace cutaway::grid
