#include "cutaway/model_frame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "grid/cell_geometry.h"

namespace cutaway::pipeline {

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
    return frame;
}

}  // namespace cutaway::pipeline
