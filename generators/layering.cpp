#include "layering.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grid/order_statistic.h"

namespace cutaway::generators {
namespace {

constexpr int kMaxZones = 4;
constexpr int kMinLayersPerZone = 5;  ///< a zone of one layer could never pinch out
constexpr double kPinchLayerCorrelation = 0.5;  ///< pinch patches of adjacent layers overlap this much
constexpr double kWeightSpread = 0.2;           ///< log-std of layer thickness variation

std::vector<int> zone_layers(const grid::GridDims& d) {
    const int zones = std::clamp(d.nz / kMinLayersPerZone, 1, kMaxZones);
    std::vector<int> first_layer;
    for (int z = 0; z <= zones; ++z) first_layer.push_back(z * d.nz / zones);
    return first_layer;
}

/// Field value below which a pillar node pinches: the `fraction` quantile of each cell's largest
/// node value, so that share of cells has all four nodes below it. Streamed a layer at a time.
float pinch_threshold(const LayeredField& field, const grid::GridDims& d, double fraction) {
    if (fraction <= 0) return -std::numeric_limits<float>::infinity();
    std::vector<float> layer(d.pillar_count());
    return grid::streamed_quantile(d.cell_count(), fraction, [&](const auto& sink) {
        for (int k = 0; k < d.nz; ++k) {
            for (int pj = 0; pj <= d.ny; ++pj)
                for (int pi = 0; pi <= d.nx; ++pi) layer[d.pillar_index(pi, pj)] = field.at(pi, pj, k);
            for (int j = 0; j < d.ny; ++j)
                for (int i = 0; i < d.nx; ++i)
                    sink(std::max({layer[d.pillar_index(i, j)], layer[d.pillar_index(i + 1, j)],
                                   layer[d.pillar_index(i, j + 1)], layer[d.pillar_index(i + 1, j + 1)]}));
        }
    });
}

float weight_of(float value) { return float(std::exp(kWeightSpread * value)); }

}  // namespace

Layering::Layering(const GeneratorParameters& p, const ModelFrame& frame, DeterministicRandom& random)
    : first_layer_(zone_layers(p.dims)),
      field_(p.dims.nx + 1, p.dims.ny + 1, p.dims.nz, frame.dx, frame.dy, p.poro_correlation_length,
             kPinchLayerCorrelation, random),
      threshold_(pinch_threshold(field_, p.dims, p.pinch_out_fraction)) {}

void Layering::pillar_weights(int pi, int pj, std::vector<float>& weights) const {
    const int nz = first_layer_.back();
    std::vector<float> values(static_cast<std::size_t>(nz));
    weights.resize(std::size_t(nz));
    for (int k = 0; k < nz; ++k) {
        values[std::size_t(k)] = field_.at(pi, pj, k);
        weights[std::size_t(k)] = values[std::size_t(k)] < threshold_ ? 0.0f : weight_of(values[std::size_t(k)]);
    }
    // A zone pinched at every layer would have nowhere to put its thickness: reopen its layer
    // with the largest field value.
    for (int z = 0; z < zones(); ++z) {
        const std::size_t first = std::size_t(first_layer_[std::size_t(z)]), end = std::size_t(first_layer_[std::size_t(z + 1)]);
        std::size_t best = first;
        bool open = false;
        for (std::size_t k = first; k < end; ++k) {
            open = open || weights[k] > 0;
            if (values[k] > values[best]) best = k;
        }
        if (!open) weights[best] = weight_of(values[best]);
    }
}

}  // namespace cutaway::generators
