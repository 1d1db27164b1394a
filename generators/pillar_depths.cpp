#include "pillar_depths.h"

#include <algorithm>

namespace cutaway::generators {
namespace {

/// Interfaces of one depth column: key horizon depths, split per zone by cumulative weights.
/// Returns how many interfaces had to be lifted to stay below the one above.
/// `weights`: the layers' weights at the pillar; `out`: NZ + 1 interfaces.
std::size_t fill_interfaces(const Layering& layering, const std::vector<float>& weights,
                            const std::vector<double>& horizon_depth, std::vector<double>& out) {
    const std::vector<int>& first_layer = layering.first_layer();
    for (int z = 0; z < layering.zones(); ++z) {
        const int first = first_layer[std::size_t(z)], end = first_layer[std::size_t(z + 1)];
        double total = 0;
        for (int k = first; k < end; ++k) total += weights[std::size_t(k)];
        const double top = horizon_depth[std::size_t(z)], span = horizon_depth[std::size_t(z + 1)] - top;
        double cumulative = 0;
        for (int k = first; k < end; ++k) {
            out[std::size_t(k)] = top + cumulative / total * span;
            cumulative += weights[std::size_t(k)];
        }
    }
    out[std::size_t(first_layer.back())] = horizon_depth.back();
    std::size_t repaired = 0;
    for (std::size_t k = 1; k <= std::size_t(first_layer.back()); ++k)
        if (out[k] < out[k - 1]) {
            out[k] = out[k - 1];
            ++repaired;
        }
    return repaired;
}

}  // namespace

PillarDepths::PillarDepths(const ModelFrame& frame, const HorizonSurfaces& horizons, const Layering& layering,
                           const std::vector<PillarLean>& leans, const std::vector<double>& offsets,
                           const grid::IjkBox& box)
    : box_(box), interfaces_(box.k1 - box.k0 + 2) {
    const grid::GridDims& d = frame.dims;
    const std::size_t box_nx = std::size_t(box.i1 - box.i0 + 1);
    corner_variant_.assign(4 * box_nx * std::size_t(box.j1 - box.j0 + 1), 0);
    depths_.reserve((box_nx + 1) * std::size_t(box.j1 - box.j0 + 2) * std::size_t(interfaces_));
    // One row of pillars at a time: its pillars' depth columns are computed on every thread (the
    // horizons' ray queries are const), then appended in pillar order, so the columns, their
    // numbering and the repair count are those of a single-threaded run.
    struct PillarColumns {
        std::vector<std::pair<double, std::vector<double>>> variants;  // offset -> interfaces, at most 4
        std::size_t repaired = 0;
    };
    const int row_length = box.i1 + 2 - box.i0;
    std::vector<PillarColumns> row(static_cast<std::size_t>(row_length));
    for (int pj = box.j0; pj <= box.j1 + 1; ++pj) {
#pragma omp parallel
        {
            std::vector<double> horizon_depth(std::size_t(horizons.count()));
            std::vector<float> weights;
            std::vector<double> column(std::size_t(d.nz + 1));  // every interface: the repair runs top down
#pragma omp for schedule(static)
            for (int pi = box.i0; pi <= box.i1 + 1; ++pi) {
                PillarColumns& out = row[std::size_t(pi - box.i0)];
                out = {};
                const std::size_t pillar = d.pillar_index(pi, pj);
                const PillarLine line{frame.pillar_x(pi), frame.pillar_y(pj), leans[pillar].x, leans[pillar].y};
                layering.pillar_weights(pi, pj, weights);
                for (int j = pj - 1; j <= pj; ++j)
                    for (int i = pi - 1; i <= pi; ++i) {
                        if (i < box.i0 || j < box.j0 || i > box.i1 || j > box.j1) continue;
                        const double offset = offsets[frame.column_index(i, j)];
                        if (std::any_of(out.variants.begin(), out.variants.end(), [&](const auto& v) { return v.first == offset; }))
                            continue;
                        for (int h = 0; h < horizons.count(); ++h)
                            horizon_depth[std::size_t(h)] = horizons.depth_on_pillar(h, line, offset);
                        out.repaired += fill_interfaces(layering, weights, horizon_depth, column);
                        out.variants.emplace_back(offset, std::vector<double>(column.begin() + box.k0, column.begin() + box.k1 + 2));
                    }
            }
        }
        for (int pi = box.i0; pi <= box.i1 + 1; ++pi) {
            const PillarColumns& out = row[std::size_t(pi - box.i0)];
            repaired_ += out.repaired;
            const std::uint32_t first_variant = std::uint32_t(depths_.size() / std::size_t(interfaces_));
            for (const auto& variant : out.variants) depths_.insert(depths_.end(), variant.second.begin(), variant.second.end());
            for (int j = pj - 1; j <= pj; ++j)
                for (int i = pi - 1; i <= pi; ++i) {
                    if (i < box.i0 || j < box.j0 || i > box.i1 || j > box.j1) continue;
                    const double offset = offsets[frame.column_index(i, j)];
                    const auto it = std::find_if(out.variants.begin(), out.variants.end(), [&](const auto& v) { return v.first == offset; });
                    const int corner = (pi - i) + 2 * (pj - j);
                    const std::size_t local = std::size_t(j - box.j0) * box_nx + std::size_t(i - box.i0);
                    corner_variant_[4 * local + std::size_t(corner)] = first_variant + std::uint32_t(it - out.variants.begin());
                }
        }
    }
}

}  // namespace cutaway::generators
