#include "cutaway/model_frame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "grid/cell_geometry.h"

namespace cutaway::pipeline {

namespace {

/// The active corners farthest along 64 directions spread over the sphere (a Fibonacci spiral).
/// The hull of the columns' top corners (of their topmost active cell) and bottom corners (of
/// their bottommost) holds every active corner: a corner lies on its pillar between those two.
std::vector<glm::vec3> model_outline(const grid::CornerPointGrid& grid, const ModelFrame& frame) {
    constexpr int directions = 64;
    std::vector<glm::vec3> axis(directions);
    for (int d = 0; d < directions; ++d) {
        const float z = 1.0f - 2.0f * (float(d) + 0.5f) / float(directions), r = std::sqrt(1.0f - z * z);
        const float phi = 2.399963f * float(d);  // the golden angle
        axis[std::size_t(d)] = {r * std::cos(phi), r * std::sin(phi), z};
    }
    std::vector<float> best(directions, -INFINITY);
    std::vector<glm::vec3> extreme(directions);
    const auto consider = [&](const grid::Point3& corner) {
        const glm::vec3 p = frame.to_render(corner);
        for (std::size_t d = 0; d < axis.size(); ++d)
            if (const float along = glm::dot(p, axis[d]); along > best[d]) {
                best[d] = along;
                extreme[d] = p;
            }
    };
    const grid::GridDims& dims = grid.dims();
    for (int j = 0; j < dims.ny; ++j)
        for (int i = 0; i < dims.nx; ++i) {
            int top = -1, bottom = -1;
            for (int k = 0; k < dims.nz; ++k)
                if (grid.active(dims.cell_index(i, j, k))) {
                    if (top < 0) top = k;
                    bottom = k;
                }
            if (top < 0) continue;
            const grid::CellCorners upper = grid::cell_corners(grid, i, j, top);
            const grid::CellCorners lower = grid::cell_corners(grid, i, j, bottom);
            for (int c = 0; c < 4; ++c) {
                consider(upper[std::size_t(c)]);
                consider(lower[std::size_t(c + 4)]);
            }
        }
    std::vector<glm::vec3> outline;
    for (const glm::vec3& p : extreme)
        if (std::find(outline.begin(), outline.end(), p) == outline.end()) outline.push_back(p);
    return outline;
}

}  // namespace

ModelFrame make_model_frame(const grid::CornerPointGrid& grid, double z_scale) {
    const grid::Box3 bounds = grid::grid_bounds(grid);
    if (bounds.empty()) throw std::invalid_argument("model has no active cell: nothing to render");
    for (double v : {bounds.min.x, bounds.min.y, bounds.min.z, bounds.max.x, bounds.max.y, bounds.max.z})
        if (!std::isfinite(v)) throw std::invalid_argument("model geometry has non-finite corner coordinates");
    ModelFrame frame;
    frame.centre = {0.5 * (bounds.min.x + bounds.max.x), 0.5 * (bounds.min.y + bounds.max.y),
                    0.5 * (bounds.min.z + bounds.max.z)};
    frame.up_sign = -double(grid.depth_direction());
    if (z_scale <= 0) {
        const double lateral = std::max(bounds.max.x - bounds.min.x, bounds.max.y - bounds.min.y);
        const double thickness = bounds.max.z - bounds.min.z;
        z_scale = thickness > 0 ? std::max(1.0, 0.2 * lateral / thickness) : 1.0;
    }
    frame.z_scale = z_scale;
    const glm::vec3 a = frame.to_render(bounds.min);
    const glm::vec3 b = frame.to_render(bounds.max);
    frame.render_min = glm::min(a, b);
    frame.render_max = glm::max(a, b);
    frame.outline = model_outline(grid, frame);
    return frame;
}

}  // namespace cutaway::pipeline
