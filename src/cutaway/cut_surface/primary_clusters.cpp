#include "cutaway/cut_surface/primary_clusters.h"

#include <stdexcept>
#include <string>

namespace cutaway::pipeline {

std::vector<IjkCellBox> primary_boxes(const std::vector<std::uint8_t>& primary, const grid::GridDims& dims) {
    if (primary.size() != dims.cell_count())
        throw std::invalid_argument("primary flags: " + std::to_string(primary.size()) + " values, expected " +
                                    std::to_string(dims.cell_count()) + " (one per cell)");
    std::vector<std::uint8_t> free = primary;  // primaries not yet in a box
    const auto index = [&](int i, int j, int k) {
        return std::size_t(i) + std::size_t(dims.nx) * (std::size_t(j) + std::size_t(dims.ny) * std::size_t(k));
    };
    const auto all_free = [&](int i0, int i1, int j0, int j1, int k0, int k1) {
        for (int k = k0; k <= k1; ++k)
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i)
                    if (!free[index(i, j, k)]) return false;
        return true;
    };
    std::vector<IjkCellBox> boxes;
    for (int k = 0; k < dims.nz; ++k)
        for (int j = 0; j < dims.ny; ++j)
            for (int i = 0; i < dims.nx; ++i) {
                if (!free[index(i, j, k)]) continue;
                IjkCellBox b{i, j, k, i, j, k};
                while (b.i1 + 1 < dims.nx && free[index(b.i1 + 1, j, k)]) ++b.i1;
                while (b.j1 + 1 < dims.ny && all_free(b.i0, b.i1, b.j1 + 1, b.j1 + 1, k, k)) ++b.j1;
                while (b.k1 + 1 < dims.nz && all_free(b.i0, b.i1, b.j0, b.j1, b.k1 + 1, b.k1 + 1)) ++b.k1;
                for (int z = b.k0; z <= b.k1; ++z)
                    for (int y = b.j0; y <= b.j1; ++y)
                        for (int x = b.i0; x <= b.i1; ++x) free[index(x, y, z)] = 0;
                boxes.push_back(b);
            }
    return boxes;
}

}  // namespace cutaway::pipeline
