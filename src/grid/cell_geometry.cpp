#include "grid/cell_geometry.h"

#include <cmath>
#include <stdexcept>

namespace cutaway::grid {

Point3 point_on_pillar(const Pillar& pillar, double z) {
    const double dz = pillar.bottom.z - pillar.top.z;
    if (dz == 0.0) return {pillar.top.x, pillar.top.y, z};
    const double t = (z - pillar.top.z) / dz;
    return {pillar.top.x + t * (pillar.bottom.x - pillar.top.x), pillar.top.y + t * (pillar.bottom.y - pillar.top.y), z};
}

CellCorners cell_corners(const CornerPointGrid& grid, int i, int j, int k) {
    if (!grid.has_corner_depths()) throw std::logic_error("cell_corners: the grid's corner depths were released");
    CellCorners corners;
    for (int c = 0; c < 8; ++c) {
        const Pillar pillar = grid.pillar(i + (c & 1), j + ((c >> 1) & 1));
        corners[std::size_t(c)] = point_on_pillar(pillar, grid.zcorn().corner_depth(i, j, k, c));
    }
    return corners;
}

Point3 cell_centre(const CellCorners& corners) {
    Point3 sum;
    for (const Point3& p : corners) {
        sum.x += p.x;
        sum.y += p.y;
        sum.z += p.z;
    }
    return {sum.x / 8.0, sum.y / 8.0, sum.z / 8.0};
}

double signed_volume(const CellCorners& corners) {
    // x(u,v,w) = sum_c N_c P_c with N_c the trilinear shape functions on [0,1]^3.
    const double g = 0.5 / std::sqrt(3.0);
    const double nodes[2] = {0.5 - g, 0.5 + g};
    double volume = 0.0;
    for (double u : nodes)
        for (double v : nodes)
            for (double w : nodes) {
                double du[3] = {0, 0, 0}, dv[3] = {0, 0, 0}, dw[3] = {0, 0, 0};
                for (int c = 0; c < 8; ++c) {
                    const double fu = (c & 1) ? u : 1 - u, su = (c & 1) ? 1 : -1;
                    const double fv = (c & 2) ? v : 1 - v, sv = (c & 2) ? 1 : -1;
                    const double fw = (c & 4) ? w : 1 - w, sw = (c & 4) ? 1 : -1;
                    // Relative to corner 0: volume is translation-invariant, and small numbers
                    // keep the rounding far below a cell's volume (and a pinched cell exactly 0).
                    const Point3& p = corners[std::size_t(c)];
                    const double xyz[3] = {p.x - corners[0].x, p.y - corners[0].y, p.z - corners[0].z};
                    for (int a = 0; a < 3; ++a) {
                        du[a] += su * fv * fw * xyz[a];
                        dv[a] += fu * sv * fw * xyz[a];
                        dw[a] += fu * fv * sw * xyz[a];
                    }
                }
                const double det = du[0] * (dv[1] * dw[2] - dv[2] * dw[1]) - du[1] * (dv[0] * dw[2] - dv[2] * dw[0]) +
                                   du[2] * (dv[0] * dw[1] - dv[1] * dw[0]);
                volume += det / 8.0;  // each Gauss weight is 1/2 per axis on [0,1]
            }
    return volume;
}

double cell_volume(const CellCorners& corners) { return std::abs(signed_volume(corners)); }

Box3 cell_bounds(const CellCorners& corners) {
    Box3 box;
    for (const Point3& p : corners) box.extend(p);
    return box;
}

CellShape classify_shape(const CornerPointGrid& grid, int i, int j, int k, double tolerance) {
    const ZcornStore& z = grid.zcorn();
    bool all_pinched = true;
    for (int c = 0; c < 4; ++c) {
        const double thickness = grid.depth_direction() * (z.corner_depth(i, j, k, c | 4) - z.corner_depth(i, j, k, c));
        if (thickness < -tolerance) return CellShape::inverted;
        if (thickness > tolerance) all_pinched = false;
    }
    return all_pinched ? CellShape::pinched : CellShape::regular;
}

bool overlaps_layer_above(const CornerPointGrid& grid, int i, int j, int k, double tolerance) {
    if (k == 0) return false;
    const ZcornStore& z = grid.zcorn();
    for (int c = 0; c < 4; ++c)
        if (grid.depth_direction() * (z.corner_depth(i, j, k, c) - z.corner_depth(i, j, k - 1, c | 4)) < -tolerance)
            return true;
    return false;
}

Box3 grid_bounds(const CornerPointGrid& grid, bool all_cells) {
    Box3 box;
    const GridDims& d = grid.dims();
    // Rows of cells split over the threads; a min/max does not depend on the order it is taken in.
#pragma omp parallel
    {
        Box3 rows_box;
#pragma omp for collapse(2) schedule(static) nowait
        for (int k = 0; k < d.nz; ++k)
            for (int j = 0; j < d.ny; ++j)
                for (int i = 0; i < d.nx; ++i)
                    if (all_cells || grid.active(d.cell_index(i, j, k))) rows_box.extend(cell_bounds(cell_corners(grid, i, j, k)));
#pragma omp critical
        box.extend(rows_box);
    }
    return box;
}

}  // namespace cutaway::grid
