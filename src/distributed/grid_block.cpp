#include "distributed/grid_block.h"

#include <stdexcept>
#include <utility>

namespace cutaway::distributed {
namespace {

/// `box` moved by minus `origin`'s lower corner.
grid::IjkBox relative_to(const grid::IjkBox& box, const grid::IjkBox& origin) {
    return {box.i0 - origin.i0, box.j0 - origin.j0, box.k0 - origin.k0,
            box.i1 - origin.i0, box.j1 - origin.j0, box.k1 - origin.k0};
}

}  // namespace

std::uint32_t GridBlock::whole_id(std::uint32_t block_id) const {
    if (block_id == 0) return 0;
    const grid::CellIjk c = grid::cell_ijk(grid.dims(), block_id - 1);
    return std::uint32_t(whole_dims.cell_index(c.i + box.i0, c.j + box.j0, c.k + box.k0) + 1);
}

grid::IjkBox GridBlock::in_source() const { return relative_to(box, source); }

GridBlock make_grid_block(const grid::CornerPointGrid& whole, const grid::IjkBox& box, double tolerance) {
    return make_grid_block(whole, grid::IjkBox::whole(whole.dims()), whole.dims(), box, tolerance);
}

GridBlock make_grid_block(const grid::CornerPointGrid& source, const grid::IjkBox& source_box,
                          const grid::GridDims& whole_dims, const grid::IjkBox& box, double tolerance) {
    const grid::IjkBox halo = grid::with_halo(box, whole_dims);
    if (!(source_box.contains({halo.i0, halo.j0, halo.k0}) && source_box.contains({halo.i1, halo.j1, halo.k1})))
        throw std::logic_error("make_grid_block: the source grid does not hold the box's halo");
    std::vector<grid::FaceClass> classes;
    {
        const grid::CornerPointGrid halo_grid = grid::extract_box(source, relative_to(halo, source_box));
        const grid::FaceClassification halo_classes(halo_grid, tolerance);
        const grid::GridDims h = halo_grid.dims();
        classes.reserve(6 * box.dims().cell_count());
        for (int k = box.k0; k <= box.k1; ++k)
            for (int j = box.j0; j <= box.j1; ++j)
                for (int i = box.i0; i <= box.i1; ++i) {
                    const std::size_t cell = h.cell_index(i - halo.i0, j - halo.j0, k - halo.k0);
                    for (int side = 0; side < 6; ++side) classes.push_back(halo_classes.at(cell, grid::FaceSide(side)));
                }
    }
    return {box, whole_dims, source_box, grid::extract_box(source, relative_to(box, source_box)),
            grid::FaceClassification(std::move(classes), tolerance)};
}

}  // namespace cutaway::distributed
