#pragma once
// Grid dimensions and the index conventions shared by every corner-point array.
#include <cstddef>

namespace cutaway::grid {

/// NX x NY x NZ cells; i runs fastest, then j, then k (Eclipse order).
struct GridDims {
    int nx = 0;
    int ny = 0;
    int nz = 0;

    std::size_t cell_count() const { return std::size_t(nx) * std::size_t(ny) * std::size_t(nz); }
    /// (NX+1)(NY+1) pillars, one COORD line (6 values) each.
    std::size_t pillar_count() const { return std::size_t(nx + 1) * std::size_t(ny + 1); }
    std::size_t coord_value_count() const { return 6 * pillar_count(); }
    /// 2NX x 2NY x 2NZ depths.
    std::size_t zcorn_value_count() const { return 8 * cell_count(); }

    std::size_t cell_index(int i, int j, int k) const {
        return (std::size_t(k) * std::size_t(ny) + std::size_t(j)) * std::size_t(nx) + std::size_t(i);
    }
    std::size_t pillar_index(int pi, int pj) const {
        return std::size_t(pj) * std::size_t(nx + 1) + std::size_t(pi);
    }
    bool contains(int i, int j, int k) const {
        return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz;
    }
    bool operator==(const GridDims&) const = default;
};

/// The (i, j, k) of a cell index.
struct CellIjk {
    int i = 0;
    int j = 0;
    int k = 0;
};

inline CellIjk cell_ijk(const GridDims& dims, std::size_t index) {
    const std::size_t layer = std::size_t(dims.nx) * std::size_t(dims.ny);
    const auto k = int(index / layer);
    const std::size_t rest = index % layer;
    return {int(rest % std::size_t(dims.nx)), int(rest / std::size_t(dims.nx)), k};
}

}  // namespace cutaway::grid
