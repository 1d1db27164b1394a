#include "cutaway/visibility/cell_bricks.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

#include "cutaway/active_cell_rank.h"
#include "grid/cell_geometry.h"

namespace cutaway::pipeline {

CellBricks build_cell_bricks(const grid::CornerPointGrid& grid, const ModelFrame& frame,
                             const std::function<void()>& corners_read) {
    const ActiveCellRank rank(grid.actnum());
    const grid::GridDims& dims = grid.dims();
    const int bx = (dims.nx + brick_side - 1) / brick_side, by = (dims.ny + brick_side - 1) / brick_side,
              bz = (dims.nz + brick_side - 1) / brick_side;
    const float pad = 1e-5f * std::max(1.0f, 2.0f * frame.radius());
    const std::ptrdiff_t brick_count = std::ptrdiff_t(bx) * by * bz;
    // Calls visit(Eclipse cell, i, j, k) for each active cell of brick `b` (x fastest), in the
    // order the list keeps.
    const auto for_each_active_cell = [&](std::ptrdiff_t b, auto&& visit) {
        const int xi = int(b % bx), yj = int(b / bx % by), zk = int(b / (std::ptrdiff_t(bx) * by));
        for (int k = zk * brick_side; k < std::min(dims.nz, (zk + 1) * brick_side); ++k)
            for (int j = yj * brick_side; j < std::min(dims.ny, (yj + 1) * brick_side); ++j)
                for (int i = xi * brick_side; i < std::min(dims.nx, (xi + 1) * brick_side); ++i) {
                    const std::size_t cell = dims.cell_index(i, j, k);
                    if (grid.active(cell)) visit(cell, i, j, k);
                }
    };
    // Three passes over the bricks, split over the threads: the active cells per brick, each
    // brick's box, then (from the running sum of the counts) its cells, once the corner depths may
    // be gone (4 bytes per cell fewer beside them); bricks without an active cell are dropped.
    std::vector<std::uint32_t> first(std::size_t(brick_count) + 1, 0);
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t b = 0; b < brick_count; ++b)
        for_each_active_cell(b, [&](std::size_t, int, int, int) { ++first[std::size_t(b) + 1]; });
    for (std::size_t b = 0; b < std::size_t(brick_count); ++b) first[b + 1] += first[b];
    CellBricks bricks;
    const float far = std::numeric_limits<float>::max();
    std::vector<glm::vec3> lo(first.size() - 1, glm::vec3(far)), hi(first.size() - 1, glm::vec3(-far));
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t b = 0; b < brick_count; ++b)
        for_each_active_cell(b, [&](std::size_t, int i, int j, int k) {
            for (const grid::Point3& p : grid::cell_corners(grid, i, j, k)) {
                const glm::vec3 r = frame.to_render(p);
                lo[std::size_t(b)] = glm::min(lo[std::size_t(b)], r);
                hi[std::size_t(b)] = glm::max(hi[std::size_t(b)], r);
            }
        });
    if (corners_read) corners_read();
    bricks.cells.resize(first.back());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t b = 0; b < brick_count; ++b) {
        // Compact index = rank among the active cells: the next Eclipse cell's is the last one's
        // + 1 (a row's active neighbours), any other is counted from ACTNUM.
        std::uint32_t slot = first[std::size_t(b)];
        std::optional<std::pair<std::size_t, std::uint32_t>> last;  // Eclipse cell, compact index
        for_each_active_cell(b, [&](std::size_t cell, int, int, int) {
            const std::uint32_t compact = last && cell == last->first + 1 ? last->second + 1 : rank(cell);
            bricks.cells[slot++] = compact;
            last.emplace(cell, compact);
        });
    }
    bricks.begin.push_back(0);
    for (std::size_t b = 0; b < std::size_t(brick_count); ++b) {
        if (first[b + 1] == first[b]) continue;  // no active cell: no brick
        bricks.begin.push_back(first[b + 1]);
        for (const glm::vec3& corner : {lo[b] - pad, hi[b] + pad})
            bricks.boxes.insert(bricks.boxes.end(), {corner.x, corner.y, corner.z, 0.0f});
    }
    return bricks;
}

}  // namespace cutaway::pipeline
