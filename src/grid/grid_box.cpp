#include "grid/grid_box.h"

#include <algorithm>
#include <utility>

namespace cutaway::grid {

CornerPointGrid extract_box(const CornerPointGrid& whole, const IjkBox& box) {
    const GridDims& d = whole.dims();
    const GridDims b = box.dims();
    std::vector<double> coord;
    coord.reserve(b.coord_value_count());
    for (int pj = box.j0; pj <= box.j1 + 1; ++pj)
        for (int pi = box.i0; pi <= box.i1 + 1; ++pi) {
            const std::size_t first = 6 * d.pillar_index(pi, pj);
            coord.insert(coord.end(), whole.coord().begin() + std::ptrdiff_t(first),
                         whole.coord().begin() + std::ptrdiff_t(first + 6));
        }
    // ZCORN in Eclipse order: per layer the top corners, then the bottom ones; rows of 2*NX.
    ZcornStore zcorn(b);
    const ZcornStore& z = whole.zcorn();
    for (int k = box.k0; k <= box.k1; ++k)
        for (int bottom = 0; bottom < 2; ++bottom)
            for (int j = box.j0; j <= box.j1; ++j)
                for (int row = 0; row < 2; ++row)
                    for (int i = box.i0; i <= box.i1; ++i)
                        for (int col = 0; col < 2; ++col) zcorn.push(z.corner_depth(i, j, k, 4 * bottom + 2 * row + col));
    std::vector<std::uint8_t> actnum;
    actnum.reserve(b.cell_count());
    for (int k = box.k0; k <= box.k1; ++k)
        for (int j = box.j0; j <= box.j1; ++j)
            for (int i = box.i0; i <= box.i1; ++i) actnum.push_back(whole.active(d.cell_index(i, j, k)) ? 1 : 0);
    CornerPointGrid block(b, std::move(coord), std::move(zcorn), std::move(actnum));
    block.metadata() = whole.metadata();
    return block;
}

IjkBox with_halo(const IjkBox& box, const GridDims& d) {
    return {std::max(box.i0 - 1, 0),        std::max(box.j0 - 1, 0),        std::max(box.k0 - 1, 0),
            std::min(box.i1 + 1, d.nx - 1), std::min(box.j1 + 1, d.ny - 1), std::min(box.k1 + 1, d.nz - 1)};
}

}  // namespace cutaway::grid
