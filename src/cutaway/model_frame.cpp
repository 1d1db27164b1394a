#include "cutaway/model_frame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "grid/cell_geometry.h"

namespace cutaway::pipeline {

namespace {

constexpr int kDirections = 64;
constexpr int kPacked = 5;  ///< per direction: along, order, x, y, z

}  // namespace

void active_layer_span(const grid::CornerPointGrid& grid, std::vector<int>& top, std::vector<int>& bottom) {
    const grid::GridDims& d = grid.dims();
    top.assign(std::size_t(d.nx) * std::size_t(d.ny), -1);
    bottom = top;
    for (int j = 0; j < d.ny; ++j)
        for (int i = 0; i < d.nx; ++i)
            for (int k = 0; k < d.nz; ++k)
                if (grid.active(d.cell_index(i, j, k))) {
                    const std::size_t column = std::size_t(j) * std::size_t(d.nx) + std::size_t(i);
                    if (top[column] < 0) top[column] = k;
                    bottom[column] = k;
                }
}

OutlineSearch::OutlineSearch(const ModelFrame& frame)
    : frame_(frame), axis_(kDirections), best_(kDirections, -INFINITY), order_(kDirections, 0), extreme_(kDirections) {
    // 64 directions spread over the sphere (a Fibonacci spiral).
    for (int d = 0; d < kDirections; ++d) {
        const float z = 1.0f - 2.0f * (float(d) + 0.5f) / float(kDirections), r = std::sqrt(1.0f - z * z);
        const float phi = 2.399963f * float(d);  // the golden angle
        axis_[std::size_t(d)] = {r * std::cos(phi), r * std::sin(phi), z};
    }
}

void OutlineSearch::consider(const glm::vec3& p, double order) {
    for (std::size_t d = 0; d < axis_.size(); ++d)
        if (const float along = glm::dot(p, axis_[d]); along > best_[d] || (along == best_[d] && order < order_[d])) {
            best_[d] = along;
            order_[d] = order;
            extreme_[d] = p;
        }
}

void OutlineSearch::consider_columns(const grid::CornerPointGrid& grid, const grid::CellIjk& origin, int whole_nx,
                                     const std::vector<int>& top, const std::vector<int>& bottom) {
    const grid::GridDims& dims = grid.dims();
    const auto holds = [&](int k) { return k >= origin.k && k < origin.k + dims.nz; };
    for (int j = 0; j < dims.ny; ++j)
        for (int i = 0; i < dims.nx; ++i) {
            const std::size_t column = std::size_t(j) * std::size_t(dims.nx) + std::size_t(i);
            if (top[column] < 0) continue;
            // The whole-model scan's order: columns j-major, then per corner the top then the bottom one.
            const double first = 8.0 * (double(j + origin.j) * whole_nx + double(i + origin.i));
            const bool upper = holds(top[column]), lower = holds(bottom[column]);
            grid::CellCorners above{}, below{};
            if (upper) above = grid::cell_corners(grid, i, j, top[column] - origin.k);
            if (lower) below = grid::cell_corners(grid, i, j, bottom[column] - origin.k);
            for (int c = 0; c < 4; ++c) {
                if (upper) consider(frame_.to_render(above[std::size_t(c)]), first + 2 * c);
                if (lower) consider(frame_.to_render(below[std::size_t(c + 4)]), first + 2 * c + 1);
            }
        }
}

std::vector<double> OutlineSearch::packed() const {
    std::vector<double> numbers;
    for (std::size_t d = 0; d < axis_.size(); ++d)
        numbers.insert(numbers.end(), {double(best_[d]), order_[d], double(extreme_[d].x), double(extreme_[d].y),
                                       double(extreme_[d].z)});
    return numbers;
}

void OutlineSearch::merge(const std::vector<double>& packed) {
    for (std::size_t d = 0; d < axis_.size(); ++d) {
        const double* n = &packed[kPacked * d];
        const float along = float(n[0]);
        if (along > best_[d] || (along == best_[d] && n[1] < order_[d])) {
            best_[d] = along;
            order_[d] = n[1];
            extreme_[d] = {float(n[2]), float(n[3]), float(n[4])};
        }
    }
}

std::vector<glm::vec3> OutlineSearch::outline() const {
    std::vector<glm::vec3> outline;
    for (const glm::vec3& p : extreme_)
        if (std::find(outline.begin(), outline.end(), p) == outline.end()) outline.push_back(p);
    return outline;
}

ModelFrame frame_from_bounds(const grid::Box3& bounds, int depth_direction, double z_scale) {
    if (bounds.empty()) throw std::invalid_argument("model has no active cell: nothing to render");
    for (double v : {bounds.min.x, bounds.min.y, bounds.min.z, bounds.max.x, bounds.max.y, bounds.max.z})
        if (!std::isfinite(v)) throw std::invalid_argument("model geometry has non-finite corner coordinates");
    ModelFrame frame;
    frame.centre = {0.5 * (bounds.min.x + bounds.max.x), 0.5 * (bounds.min.y + bounds.max.y),
                    0.5 * (bounds.min.z + bounds.max.z)};
    frame.up_sign = -double(depth_direction);
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

ModelFrame make_model_frame(const grid::CornerPointGrid& grid, double z_scale) {
    return make_model_frame(grid, grid::grid_bounds(grid), z_scale);
}

ModelFrame make_model_frame(const grid::CornerPointGrid& grid, const grid::Box3& bounds, double z_scale) {
    ModelFrame frame = frame_from_bounds(bounds, grid.depth_direction(), z_scale);
    std::vector<int> top, bottom;
    active_layer_span(grid, top, bottom);
    OutlineSearch search(frame);
    search.consider_columns(grid, {0, 0, 0}, grid.dims().nx, top, bottom);
    frame.outline = search.outline();
    return frame;
}

}  // namespace cutaway::pipeline
