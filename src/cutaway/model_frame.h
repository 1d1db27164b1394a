#pragma once
// Model units to render space: centred on the active cells' bounding box (so float precision
// holds for UTM-sized coordinates), depth flipped to "up", vertical exaggeration applied.
// Render space: X east, Y north, Z up, model units (Z scaled by z_scale).
#include <vector>

#include <glm/glm.hpp>

#include "grid/corner_point_grid.h"

namespace cutaway::pipeline {

struct ModelFrame {
    grid::Point3 centre;   ///< model units, subtracted before converting to float
    double z_scale = 1;    ///< vertical exaggeration
    double up_sign = -1;   ///< render Z = up_sign * (z - centre.z) * z_scale (-1 when z is depth)
    glm::vec3 render_min{0};  ///< render-space bounds of the active cells
    glm::vec3 render_max{0};
    /// Render-space points whose hull holds the model (at most 64: the active corners farthest
    /// along 64 directions), for framing the model itself rather than its bounding box; empty
    /// means: use the box's corners.
    std::vector<glm::vec3> outline;

    glm::vec3 to_render(const grid::Point3& p) const {
        return {float(p.x - centre.x), float(p.y - centre.y), float(up_sign * (p.z - centre.z) * z_scale)};
    }
    float radius() const { return 0.5f * glm::length(render_max - render_min); }
};

/// `z_scale` <= 0 picks one automatically: the smallest exaggeration >= 1 that makes the model's
/// thickness at least 1/5 of its larger horizontal extent (reservoirs are often 100x wider than
/// thick). Throws std::invalid_argument when the grid has no active cell.
ModelFrame make_model_frame(const grid::CornerPointGrid& grid, double z_scale);

}  // namespace cutaway::pipeline
