#include "cutaway/visibility/cell_bricks.h"

#include <algorithm>
#include <limits>

#include "grid/cell_geometry.h"

namespace cutaway::pipeline {

CellBricks build_cell_bricks(const grid::CornerPointGrid& grid, const std::vector<std::uint32_t>& compact_of_cell,
                             const ModelFrame& frame) {
    const grid::GridDims& dims = grid.dims();
    const int bx = (dims.nx + brick_side - 1) / brick_side, by = (dims.ny + brick_side - 1) / brick_side,
              bz = (dims.nz + brick_side - 1) / brick_side;
    const float pad = 1e-5f * std::max(1.0f, 2.0f * frame.radius());
    CellBricks bricks;
    bricks.cells.reserve(grid.active_count());
    bricks.begin.push_back(0);
    for (int zk = 0; zk < bz; ++zk)
        for (int yj = 0; yj < by; ++yj)
            for (int xi = 0; xi < bx; ++xi) {
                glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
                const std::size_t first = bricks.cells.size();
                for (int k = zk * brick_side; k < std::min(dims.nz, (zk + 1) * brick_side); ++k)
                    for (int j = yj * brick_side; j < std::min(dims.ny, (yj + 1) * brick_side); ++j)
                        for (int i = xi * brick_side; i < std::min(dims.nx, (xi + 1) * brick_side); ++i) {
                            const std::uint32_t compact = compact_of_cell[dims.cell_index(i, j, k)];
                            if (compact == std::numeric_limits<std::uint32_t>::max()) continue;
                            bricks.cells.push_back(compact);
                            for (const grid::Point3& p : grid::cell_corners(grid, i, j, k)) {
                                const glm::vec3 r = frame.to_render(p);
                                lo = glm::min(lo, r);
                                hi = glm::max(hi, r);
                            }
                        }
                if (bricks.cells.size() == first) continue;  // no active cell: no brick
                bricks.begin.push_back(std::uint32_t(bricks.cells.size()));
                for (const glm::vec3& corner : {lo - pad, hi + pad})
                    bricks.boxes.insert(bricks.boxes.end(), {corner.x, corner.y, corner.z, 0.0f});
            }
    return bricks;
}

}  // namespace cutaway::pipeline
