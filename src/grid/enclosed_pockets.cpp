#include "grid/enclosed_pockets.h"

#include <cstdint>

#include "grid/face_classification.h"

namespace cutaway::grid {

std::vector<bool> enclosed_inactive_cells(const ZcornStore& zcorn, const std::vector<bool>& active, double tolerance) {
    const GridDims& d = zcorn.dims();
    std::vector<bool> enclosed(d.cell_count(), false), visited(d.cell_count(), false);
    // 4-byte cell indices (a group or the stack can hold every inactive cell); a grid beyond them
    // is left with nothing enclosed, which only keeps faces.
    if (d.cell_count() > UINT32_MAX) return enclosed;
    std::vector<std::uint32_t> group, stack;
    for (std::size_t first = 0; first < d.cell_count(); ++first) {
        if (active[first] || visited[first]) continue;
        // Depth-first over the group of inactive cells that contains `first`.
        group.clear();
        stack.assign(1, std::uint32_t(first));
        visited[first] = true;
        bool walled_in = true;
        while (!stack.empty()) {
            const std::uint32_t cell = stack.back();
            stack.pop_back();
            group.push_back(cell);
            const CellIjk at = cell_ijk(d, cell);
            for (int s = 0; s < 6; ++s) {
                const CellIjk n = across(at, FaceSide(s));
                if (!d.contains(n.i, n.j, n.k)) {
                    walled_in = false;  // on a side of the grid
                    continue;
                }
                if (walled_in && !faces_meet(zcorn, at.i, at.j, at.k, FaceSide(s), tolerance)) walled_in = false;
                const std::size_t next = d.cell_index(n.i, n.j, n.k);
                if (!active[next] && !visited[next]) {
                    visited[next] = true;
                    stack.push_back(std::uint32_t(next));
                }
            }
        }
        if (walled_in)
            for (const std::uint32_t cell : group) enclosed[cell] = true;
    }
    return enclosed;
}

}  // namespace cutaway::grid
