#include "distributed/grid_block.h"

#include <algorithm>
#include <utility>

namespace cutaway::distributed {
namespace {

grid::GridDims dims_of(const grid::IjkBox& box) { return {box.i1 - box.i0 + 1, box.j1 - box.j0 + 1, box.k1 - box.k0 + 1}; }

/// `box` grown by one cell on every side, within the grid.
grid::IjkBox with_halo(const grid::IjkBox& box, const grid::GridDims& d) {
    return {std::max(box.i0 - 1, 0),    std::max(box.j0 - 1, 0),    std::max(box.k0 - 1, 0),
            std::min(box.i1 + 1, d.nx - 1), std::min(box.j1 + 1, d.ny - 1), std::min(box.k1 + 1, d.nz - 1)};
}

}  // namespace

grid::CornerPointGrid extract_box(const grid::CornerPointGrid& whole, const grid::IjkBox& box) {
    const grid::GridDims& d = whole.dims();
    const grid::GridDims b = dims_of(box);
    std::vector<double> coord;
    coord.reserve(b.coord_value_count());
    for (int pj = box.j0; pj <= box.j1 + 1; ++pj)
        for (int pi = box.i0; pi <= box.i1 + 1; ++pi) {
            const std::size_t first = 6 * d.pillar_index(pi, pj);
            coord.insert(coord.end(), whole.coord().begin() + std::ptrdiff_t(first),
                         whole.coord().begin() + std::ptrdiff_t(first + 6));
        }
    // ZCORN in Eclipse order: per layer the top corners, then the bottom ones; rows of 2*NX.
    grid::ZcornStore zcorn(b);
    const grid::ZcornStore& z = whole.zcorn();
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
    grid::CornerPointGrid block(b, std::move(coord), std::move(zcorn), std::move(actnum));
    block.metadata() = whole.metadata();
    return block;
}

std::uint32_t GridBlock::whole_id(std::uint32_t block_id) const {
    if (block_id == 0) return 0;
    const grid::CellIjk c = grid::cell_ijk(grid.dims(), block_id - 1);
    return std::uint32_t(whole_dims.cell_index(c.i + box.i0, c.j + box.j0, c.k + box.k0) + 1);
}

GridBlock make_grid_block(const grid::CornerPointGrid& whole, const grid::IjkBox& box, double tolerance) {
    const grid::IjkBox halo = with_halo(box, whole.dims());
    std::vector<grid::FaceClass> classes;
    {
        const grid::CornerPointGrid halo_grid = extract_box(whole, halo);
        const grid::FaceClassification halo_classes(halo_grid, tolerance);
        const grid::GridDims h = halo_grid.dims();
        classes.reserve(6 * dims_of(box).cell_count());
        for (int k = box.k0; k <= box.k1; ++k)
            for (int j = box.j0; j <= box.j1; ++j)
                for (int i = box.i0; i <= box.i1; ++i) {
                    const std::size_t cell = h.cell_index(i - halo.i0, j - halo.j0, k - halo.k0);
                    for (int side = 0; side < 6; ++side) classes.push_back(halo_classes.at(cell, grid::FaceSide(side)));
                }
    }
    return {box, whole.dims(), extract_box(whole, box), grid::FaceClassification(std::move(classes), tolerance)};
}

}  // namespace cutaway::distributed
