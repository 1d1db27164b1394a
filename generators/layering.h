#pragma once
// Stratigraphic layering between key horizons: each zone (the rock between two key horizons)
// is split into layers in proportion to per-pillar weights; a weight of zero is a pinch-out
// (the layer has no thickness at that pillar).
#include <vector>

#include "deterministic_random.h"
#include "generator_parameters.h"
#include "model_frame.h"

namespace cutaway::generators {

struct Layering {
    /// first_layer[z] .. first_layer[z+1]-1 are zone z's layers; size zones + 1, last = NZ.
    std::vector<int> first_layer;
    /// Weight of layer k at pillar p, index k * pillar_count + p; 0 where the layer pinches out.
    std::vector<float> weights;

    int zones() const { return int(first_layer.size()) - 1; }
};

/// clamp(NZ / 5, 1, 4) zones of near-equal layer counts; pinch-outs placed in correlated patches so that
/// about `pinch_out_fraction` of the cells have all four pillar edges pinched. Every zone keeps
/// at least one layer with thickness at every pillar.
Layering make_layering(const GeneratorParameters& parameters, const ModelFrame& frame, DeterministicRandom& random);

}  // namespace cutaway::generators
