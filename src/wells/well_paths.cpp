#include "wells/well_paths.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grid/cell_geometry.h"

namespace cutaway::wells {
namespace {

/// The centre of column (i, j) at depth z: the mean of its 4 pillars there.
grid::Point3 column_point(const grid::CornerPointGrid& grid, int i, int j, double z) {
    grid::Point3 sum;
    for (int c = 0; c < 4; ++c) {
        const grid::Point3 p = grid::point_on_pillar(grid.pillar(i + (c & 1), j + (c >> 1)), z);
        sum = {sum.x + p.x, sum.y + p.y, sum.z + p.z};
    }
    return {sum.x / 4, sum.y / 4, sum.z / 4};
}

bool same_point(const grid::Point3& a, const grid::Point3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

double distance_xy(const grid::Point3& a, const grid::Point3& b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

WellheadLevel wellhead_level(const grid::Box3& box, int depth_direction) {
    const double thickness = box.empty() ? 0.0 : box.max.z - box.min.z;
    // depth_direction +1: depths grow downwards, so the top is the smallest z.
    const bool depths_down = depth_direction > 0;
    WellheadLevel level;
    level.top = box.empty() ? 0.0 : (depths_down ? box.min.z : box.max.z);
    level.head = level.top + (depths_down ? -0.25 : 0.25) * thickness;
    return level;
}

WellheadLevel wellhead_level(const grid::CornerPointGrid& grid) { return wellhead_level(grid::grid_bounds(grid), grid.depth_direction()); }

std::vector<grid::Point3> well_path_points(const Well& well, const grid::CornerPointGrid& part, const WellheadLevel& level,
                                           const grid::CellIjk& origin) {
    const grid::GridDims& d = part.dims();
    const double none = -std::numeric_limits<double>::infinity();
    const grid::Point3 unknown{none, none, none};
    std::vector<grid::Point3> points(2 + well.connections.size(), unknown);
    const int hi = well.head_i - origin.i, hj = well.head_j - origin.j;
    if (hi >= 0 && hj >= 0 && hi < d.nx && hj < d.ny) {
        points[0] = column_point(part, hi, hj, level.head);
        points[1] = column_point(part, hi, hj, level.top);
    }
    for (std::size_t c = 0; c < well.connections.size(); ++c) {
        const WellConnection& w = well.connections[c];
        if (d.contains(w.i - origin.i, w.j - origin.j, w.k - origin.k))
            points[2 + c] = grid::cell_centre(grid::cell_corners(part, w.i - origin.i, w.j - origin.j, w.k - origin.k));
    }
    return points;
}

std::vector<grid::Point3> assemble_well_path(const Well& well, const std::vector<grid::Point3>& points) {
    const grid::Point3 &head = points[0], &top = points[1];
    std::vector<grid::Point3> path{head};
    for (std::size_t c = 0; c < well.connections.size(); ++c) {
        const WellConnection& connection = well.connections[c];
        const grid::Point3& centre = points[2 + c];
        if (c == 0 && (connection.i != well.head_i || connection.j != well.head_j)) {
            // The head's column at the connection's depth, along the column's straight line.
            const double t = top.z != head.z ? (centre.z - head.z) / (top.z - head.z) : 0.0;
            path.push_back({head.x + t * (top.x - head.x), head.y + t * (top.y - head.y), centre.z});
        }
        if (!same_point(centre, path.back())) path.push_back(centre);
    }
    if (path.size() < 2) path.push_back(top);
    return path;
}

std::vector<grid::Point3> well_path(const Well& well, const grid::CornerPointGrid& grid, const WellheadLevel& level) {
    return assemble_well_path(well, well_path_points(well, grid, level));
}

WellPathMap well_paths(const std::vector<Well>& wells, const grid::CornerPointGrid& grid) {
    const WellheadLevel level = wellhead_level(grid);
    WellPathMap paths;
    for (const Well& well : wells) paths[well.name] = well_path(well, grid, level);
    return paths;
}

std::optional<std::vector<grid::Point3>> find_well_path(const WellPathMap& paths, const std::string& name) {
    const auto found = paths.find(name);
    if (found == paths.end()) return std::nullopt;
    return found->second;
}

double default_well_radius(const grid::CornerPointGrid& grid) { return default_well_radius(grid, grid::grid_bounds(grid)); }

double default_well_radius(const grid::CornerPointGrid& grid, const grid::Box3& box) {
    const grid::GridDims& d = grid.dims();
    // Up to about 4096 columns, evenly strided: a median needs no more.
    const std::size_t columns = std::size_t(d.nx) * std::size_t(d.ny);
    const std::size_t stride = std::max<std::size_t>(1, columns / 4096);
    std::vector<double> widths;
    for (std::size_t column = 0; column < columns; column += stride) {
        const int i = int(column % std::size_t(d.nx)), j = int(column / std::size_t(d.nx));
        const grid::Point3 origin = grid.pillar(i, j).top;
        const double width = std::min(distance_xy(origin, grid.pillar(i + 1, j).top), distance_xy(origin, grid.pillar(i, j + 1).top));
        if (width > 0 && std::isfinite(width)) widths.push_back(width);
    }
    const double diagonal = box.empty() ? 0.0 : std::hypot(box.max.x - box.min.x, box.max.y - box.min.y);
    double median = 0;
    if (!widths.empty()) {
        std::nth_element(widths.begin(), widths.begin() + std::ptrdiff_t(widths.size() / 2), widths.end());
        median = widths[widths.size() / 2];
    }
    const double radius = std::max(0.2 * median, 0.003 * diagonal);
    return radius > 0 ? radius : 1.0;
}

}  // namespace cutaway::wells
