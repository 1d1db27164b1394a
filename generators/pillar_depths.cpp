#include "pillar_depths.h"

#include <algorithm>

namespace cutaway::generators {
namespace {

/// Interfaces of one depth column: key horizon depths, split per zone by cumulative weights.
/// Returns how many interfaces had to be lifted to stay below the one above.
std::size_t fill_interfaces(const Layering& layering, std::size_t pillar, std::size_t pillars,
                            const std::vector<double>& horizon_depth, double* out) {
    for (int z = 0; z < layering.zones(); ++z) {
        const int first = layering.first_layer[std::size_t(z)], end = layering.first_layer[std::size_t(z + 1)];
        double total = 0;
        for (int k = first; k < end; ++k) total += layering.weights[std::size_t(k) * pillars + pillar];
        const double top = horizon_depth[std::size_t(z)], span = horizon_depth[std::size_t(z + 1)] - top;
        double cumulative = 0;
        for (int k = first; k < end; ++k) {
            out[k] = top + cumulative / total * span;
            cumulative += layering.weights[std::size_t(k) * pillars + pillar];
        }
    }
    out[layering.first_layer.back()] = horizon_depth.back();
    std::size_t repaired = 0;
    for (int k = 1; k <= layering.first_layer.back(); ++k)
        if (out[k] < out[k - 1]) {
            out[k] = out[k - 1];
            ++repaired;
        }
    return repaired;
}

}  // namespace

PillarDepths::PillarDepths(const ModelFrame& frame, const HorizonSurfaces& horizons, const Layering& layering,
                           const std::vector<PillarLean>& leans, const std::vector<double>& offsets)
    : nx_(frame.dims.nx), interfaces_(frame.dims.nz + 1) {
    const grid::GridDims& d = frame.dims;
    const std::size_t pillars = d.pillar_count();
    corner_variant_.assign(4 * frame.column_count(), 0);
    depths_.reserve(pillars * std::size_t(interfaces_));
    std::vector<double> horizon_depth(std::size_t(horizons.count()));
    for (int pj = 0; pj <= d.ny; ++pj)
        for (int pi = 0; pi <= d.nx; ++pi) {
            const std::size_t pillar = d.pillar_index(pi, pj);
            const PillarLine line{frame.pillar_x(pi), frame.pillar_y(pj), leans[pillar].x, leans[pillar].y};
            std::vector<std::pair<double, std::uint32_t>> seen;  // offset -> variant, at most 4
            for (int j = pj - 1; j <= pj; ++j)
                for (int i = pi - 1; i <= pi; ++i) {
                    if (i < 0 || j < 0 || i >= d.nx || j >= d.ny) continue;
                    const double offset = offsets[frame.column_index(i, j)];
                    auto it = std::find_if(seen.begin(), seen.end(), [&](const auto& s) { return s.first == offset; });
                    if (it == seen.end()) {
                        for (int h = 0; h < horizons.count(); ++h)
                            horizon_depth[std::size_t(h)] = horizons.depth_on_pillar(h, line, offset);
                        const std::size_t start = depths_.size();
                        depths_.resize(start + std::size_t(interfaces_));
                        repaired_ += fill_interfaces(layering, pillar, pillars, horizon_depth, &depths_[start]);
                        seen.emplace_back(offset, std::uint32_t(start / std::size_t(interfaces_)));
                        it = seen.end() - 1;
                    }
                    const int corner = (pi - i) + 2 * (pj - j);
                    corner_variant_[4 * frame.column_index(i, j) + std::size_t(corner)] = it->second;
                }
        }
}

}  // namespace cutaway::generators
