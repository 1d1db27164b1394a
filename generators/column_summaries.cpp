#include "column_summaries.h"

#include <algorithm>
#include <stdexcept>

#include "grid/cell_geometry.h"

namespace cutaway::generators {
namespace {

const std::vector<float>& required_property(const grid::CornerPointGrid& grid, const char* name) {
    const std::vector<float>* values = grid.property(name);
    if (!values) throw std::invalid_argument(std::string("--deck: expected the model's ") + name + ", found none");
    return *values;
}

/// Mean height of the cell's four pillar edges (bottom corner depth minus top corner depth).
double cell_thickness(const grid::CellCorners& corners) {
    double sum = 0;
    for (int c = 0; c < 4; ++c) sum += corners[std::size_t(c + 4)].z - corners[std::size_t(c)].z;
    return 0.25 * sum;
}

}  // namespace

std::vector<ColumnSummary> active_columns(const grid::CornerPointGrid& grid) {
    const std::vector<float>& permx = required_property(grid, "PERMX");
    const std::vector<float>& ntg = required_property(grid, "NTG");
    if (grid.depth_direction() < 0)
        throw std::invalid_argument("--deck: expected depths growing with k (z down), found them shrinking");
    const grid::GridDims& d = grid.dims();
    std::vector<ColumnSummary> columns;
    for (int j = 0; j < d.ny; ++j)
        for (int i = 0; i < d.nx; ++i) {
            ColumnSummary column;
            column.i = i;
            column.j = j;
            for (int k = 0; k < d.nz; ++k) {
                const std::size_t cell = d.cell_index(i, j, k);
                if (!grid.active(cell)) continue;
                const grid::CellCorners corners = grid::cell_corners(grid, i, j, k);
                const double thickness = cell_thickness(corners);
                if (!(thickness > 0)) continue;
                const grid::Point3 centre = grid::cell_centre(corners);
                if (column.layers.empty()) column.top_depth = centre.z;
                column.layers.push_back(k);
                column.x += centre.x;
                column.y += centre.y;
                column.kh += double(permx[cell]) * double(ntg[cell]) * thickness;
                column.footprint += grid::cell_volume(corners) / thickness;
            }
            if (column.layers.empty()) continue;
            const double n = double(column.layers.size());
            column.x /= n;
            column.y /= n;
            column.footprint /= n;
            columns.push_back(std::move(column));
        }
    std::vector<double> kh(std::size_t(d.nx) * std::size_t(d.ny), 0.0);  // per column, i fastest; 0 without active cells
    for (const ColumnSummary& c : columns) kh[std::size_t(c.j) * std::size_t(d.nx) + std::size_t(c.i)] = c.kh;
    for (ColumnSummary& c : columns)
        for (int j = std::max(c.j - 1, 0); j <= std::min(c.j + 1, d.ny - 1); ++j)
            for (int i = std::max(c.i - 1, 0); i <= std::min(c.i + 1, d.nx - 1); ++i)
                c.neighbourhood_kh += kh[std::size_t(j) * std::size_t(d.nx) + std::size_t(i)];
    return columns;
}

}  // namespace cutaway::generators
