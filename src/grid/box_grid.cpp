#include "grid/box_grid.h"

#include <cmath>

namespace cutaway::grid {

CornerPointGrid make_box_grid(const BoxGridSpec& spec) {
    const GridDims& d = spec.dims;
    std::vector<double> coord;
    coord.reserve(d.coord_value_count());
    const double bottom = spec.origin.z + (d.nz + 1) * spec.cell_size.z + std::abs(spec.fault_throw);
    for (int pj = 0; pj <= d.ny; ++pj)
        for (int pi = 0; pi <= d.nx; ++pi) {
            const double x = spec.origin.x + pi * spec.cell_size.x, y = spec.origin.y + pj * spec.cell_size.y;
            coord.insert(coord.end(), {x, y, spec.origin.z, x, y, bottom});
        }
    ZcornStore zcorn(d);
    for (int k = 0; k < d.nz; ++k)
        for (int face = 0; face < 2; ++face)
            for (int row = 0; row < 2 * d.ny; ++row)
                for (int col = 0; col < 2 * d.nx; ++col) {
                    const int i = col / 2;
                    const double shift = (spec.fault_throw != 0 && i >= spec.fault_i) ? spec.fault_throw : 0.0;
                    zcorn.push(spec.origin.z + (k + face) * spec.cell_size.z + shift);
                }
    return CornerPointGrid(d, std::move(coord), std::move(zcorn), {});
}

}  // namespace cutaway::grid
