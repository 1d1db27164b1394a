#include "layering.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "smooth_field.h"

namespace cutaway::generators {
namespace {

constexpr int kMaxZones = 4;
constexpr int kMinLayersPerZone = 5;  ///< a zone of one layer could never pinch out
constexpr double kPinchLayerCorrelation = 0.5;  ///< pinch patches of adjacent layers overlap this much
constexpr double kWeightSpread = 0.2;           ///< log-std of layer thickness variation

/// Field value below which a pillar node pinches: the `fraction` quantile of each cell's largest
/// node value, so that share of cells has all four nodes below it.
float pinch_threshold(const std::vector<float>& field, const grid::GridDims& d, double fraction) {
    if (fraction <= 0) return -std::numeric_limits<float>::infinity();
    std::vector<float> cell_max(d.cell_count());
    std::size_t n = 0;
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i) {
                const std::size_t base = std::size_t(k) * d.pillar_count();
                cell_max[n++] = std::max({field[base + d.pillar_index(i, j)], field[base + d.pillar_index(i + 1, j)],
                                          field[base + d.pillar_index(i, j + 1)],
                                          field[base + d.pillar_index(i + 1, j + 1)]});
            }
    return quantile(std::move(cell_max), fraction);
}

}  // namespace

Layering make_layering(const GeneratorParameters& p, const ModelFrame& frame, DeterministicRandom& random) {
    const grid::GridDims& d = p.dims;
    Layering layering;
    const int zones = std::clamp(d.nz / kMinLayersPerZone, 1, kMaxZones);
    for (int z = 0; z <= zones; ++z) layering.first_layer.push_back(z * d.nz / zones);

    const std::vector<float> field = layered_field(d.nx + 1, d.ny + 1, d.nz, frame.dx, frame.dy,
                                                   p.poro_correlation_length, kPinchLayerCorrelation, random);
    const float threshold = pinch_threshold(field, d, p.pinch_out_fraction);
    const std::size_t pillars = d.pillar_count();
    layering.weights.resize(field.size());
    for (std::size_t n = 0; n < field.size(); ++n)
        layering.weights[n] = field[n] < threshold ? 0.0f : float(std::exp(kWeightSpread * field[n]));
    // A zone pinched at every layer would have nowhere to put its thickness: reopen its layer
    // with the largest field value.
    for (int z = 0; z < zones; ++z)
        for (std::size_t pillar = 0; pillar < pillars; ++pillar) {
            std::size_t best = std::size_t(layering.first_layer[std::size_t(z)]) * pillars + pillar;
            bool open = false;
            for (int k = layering.first_layer[std::size_t(z)]; k < layering.first_layer[std::size_t(z + 1)]; ++k) {
                const std::size_t n = std::size_t(k) * pillars + pillar;
                open = open || layering.weights[n] > 0;
                if (field[n] > field[best]) best = n;
            }
            if (!open) layering.weights[best] = float(std::exp(kWeightSpread * field[best]));
        }
    return layering;
}

}  // namespace cutaway::generators
