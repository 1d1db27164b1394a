#pragma once
// Model units to render space: centred on the active cells' bounding box (so float precision
// holds for UTM-sized coordinates), depth flipped to "up", vertical exaggeration applied.
// Render space: X east, Y north, Z up, model units (Z scaled by z_scale).
#include <vector>

#include "grid/point3.h"

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
    /// Render-space points drawn with the model that a framed camera keeps in view beside it: the
    /// wellheads of the wells drawn, which stand above the model's top (keep_wellheads_in_view).
    std::vector<glm::vec3> drawn_with;

    glm::vec3 to_render(const grid::Point3& p) const {
        return {float(p.x - centre.x), float(p.y - centre.y), float(up_sign * (p.z - centre.z) * z_scale)};
    }
    float radius() const { return 0.5f * glm::length(render_max - render_min); }
};

/// `z_scale` <= 0 picks one automatically: the smallest exaggeration >= 1 that makes the model's
/// thickness at least 1/5 of its larger horizontal extent (reservoirs are often 100x wider than
/// thick). Throws std::invalid_argument when the grid has no active cell.
ModelFrame make_model_frame(const grid::CornerPointGrid& grid, double z_scale);
/// The same for a grid whose active cells span `bounds` (grid::grid_bounds, computed once by a
/// caller that needs it for more than the frame).
ModelFrame make_model_frame(const grid::CornerPointGrid& grid, const grid::Box3& bounds, double z_scale);

/// make_model_frame without the outline, for a model whose active cells span `bounds` and whose
/// depths grow with k (`depth_direction` +1) or shrink (-1).
ModelFrame frame_from_bounds(const grid::Box3& bounds, int depth_direction, double z_scale);

/// The top-most and bottom-most active layer of every column of `grid` (i fastest; -1: none).
void active_layer_span(const grid::CornerPointGrid& grid, std::vector<int>& top, std::vector<int>& bottom);

/// The outline's search: the farthest active corner along each of 64 directions, among the
/// corners of each column's top-most and bottom-most active cells (their hull holds every active
/// corner: a corner lies on its pillar between those two). Ties go to the candidate the
/// whole-model scan meets first, so candidates offered in any order, and searches over parts of
/// the model merged, give make_model_frame's outline bit for bit.
class OutlineSearch {
public:
    explicit OutlineSearch(const ModelFrame& frame);
    /// The candidates of the columns of `grid`, the cells from `origin` on of a model `whole`
    /// columns wide: `top` and `bottom` hold, per column of `grid` (i fastest), the whole model's
    /// top-most and bottom-most active layer of that column (-1: none); corners of cells outside
    /// `grid`'s layers are left to the part that holds them.
    void consider_columns(const grid::CornerPointGrid& grid, const grid::CellIjk& origin, int whole_nx,
                          const std::vector<int>& top, const std::vector<int>& bottom);
    /// The search as numbers (5 per direction) for another part to merge().
    std::vector<double> packed() const;
    void merge(const std::vector<double>& packed);
    /// The distinct extreme corners, in direction order (ModelFrame::outline).
    std::vector<glm::vec3> outline() const;

private:
    void consider(const glm::vec3& point, double order);
    ModelFrame frame_;
    std::vector<glm::vec3> axis_;
    std::vector<float> best_;
    std::vector<double> order_;
    std::vector<glm::vec3> extreme_;
};

}  // namespace cutaway::pipeline
