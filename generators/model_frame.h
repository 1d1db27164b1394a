#pragma once
// The regular lattice the model is laid out on before faulting: pillar (pi, pj) stands at
// (pi * dx, pj * dy) at mid-depth; column (i, j) is the cell column between pillars i..i+1, j..j+1.
#include "generator_parameters.h"
#include "grid/point3.h"

namespace cutaway::generators {

struct ModelFrame {
    grid::GridDims dims;
    double dx = 1;         ///< lateral cell size east, metres
    double dy = 1;         ///< lateral cell size north, metres
    double mid_depth = 0;  ///< depth where untilted and tilted pillars meet, metres

    static ModelFrame from(const GeneratorParameters& p) {
        return {p.dims, p.length_x / p.dims.nx, p.length_y / p.dims.ny, p.top_depth + 0.5 * p.thickness};
    }
    double pillar_x(int pi) const { return pi * dx; }
    double pillar_y(int pj) const { return pj * dy; }
    grid::Point3 column_centre(int i, int j) const { return {(i + 0.5) * dx, (j + 0.5) * dy, mid_depth}; }
    std::size_t column_index(int i, int j) const { return std::size_t(j) * std::size_t(dims.nx) + std::size_t(i); }
    std::size_t column_count() const { return std::size_t(dims.nx) * std::size_t(dims.ny); }
};

}  // namespace cutaway::generators
