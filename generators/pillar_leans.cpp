#include "pillar_leans.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cutaway::generators {

bool on_fault_trace(const ModelFrame& frame, const std::vector<std::uint64_t>& masks, int pi, int pj, int f) {
    bool seen[2] = {false, false};
    for (int j = pj - 1; j <= pj; ++j)
        for (int i = pi - 1; i <= pi; ++i) {
            if (i < 0 || j < 0 || i >= frame.dims.nx || j >= frame.dims.ny) continue;
            seen[masks[frame.column_index(i, j)] >> f & 1] = true;
        }
    return seen[0] && seen[1];
}

namespace {

/// Largest scale s <= 1 keeping pillars i and i+1 (and j, j+1) at least half a cell apart
/// along their lattice direction at every depth within `depth_reach` of mid-depth.
double non_crossing_scale(const ModelFrame& frame, const std::vector<PillarLean>& leans, double depth_reach) {
    const grid::GridDims& d = frame.dims;
    double worst_x = 0, worst_y = 0;  // largest lean difference between lattice neighbours
    for (int pj = 0; pj <= d.ny; ++pj)
        for (int pi = 0; pi <= d.nx; ++pi) {
            const PillarLean& here = leans[d.pillar_index(pi, pj)];
            if (pi < d.nx) worst_x = std::max(worst_x, std::abs(leans[d.pillar_index(pi + 1, pj)].x - here.x));
            if (pj < d.ny) worst_y = std::max(worst_y, std::abs(leans[d.pillar_index(pi, pj + 1)].y - here.y));
        }
    double scale = 1;
    if (worst_x * depth_reach > 0.5 * frame.dx) scale = std::min(scale, 0.5 * frame.dx / (worst_x * depth_reach));
    if (worst_y * depth_reach > 0.5 * frame.dy) scale = std::min(scale, 0.5 * frame.dy / (worst_y * depth_reach));
    return scale;
}

}  // namespace

PillarLeans pillar_leans(const ModelFrame& frame, const std::vector<FaultPlane>& faults,
                         const std::vector<std::uint64_t>& masks, int spread, double depth_reach) {
    const grid::GridDims& d = frame.dims;
    std::vector<PillarLean> leans(d.pillar_count());
    std::vector<float> share(d.pillar_count());
    for (std::size_t f = 0; f < faults.size(); ++f) {
        if (faults[f].lean_x == 0 && faults[f].lean_y == 0) continue;
        std::fill(share.begin(), share.end(), 0.0f);
        for (int pj = 0; pj <= d.ny; ++pj)
            for (int pi = 0; pi <= d.nx; ++pi) {
                if (!on_fault_trace(frame, masks, pi, pj, int(f))) continue;
                for (int qj = std::max(0, pj - spread); qj <= std::min(d.ny, pj + spread); ++qj)
                    for (int qi = std::max(0, pi - spread); qi <= std::min(d.nx, pi + spread); ++qi) {
                        const int r = std::max(std::abs(qi - pi), std::abs(qj - pj));
                        float& s = share[d.pillar_index(qi, qj)];
                        s = std::max(s, 1.0f - float(r) / float(spread + 1));
                    }
            }
        for (std::size_t p = 0; p < leans.size(); ++p) {
            leans[p].x += share[p] * faults[f].lean_x;
            leans[p].y += share[p] * faults[f].lean_y;
        }
    }
    const double scale = non_crossing_scale(frame, leans, depth_reach);
    for (PillarLean& lean : leans) {
        lean.x *= scale;
        lean.y *= scale;
    }
    return {std::move(leans), scale};
}

}  // namespace cutaway::generators
