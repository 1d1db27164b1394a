#pragma once
// Stratigraphic layering between key horizons: each zone (the rock between two key horizons)
// is split into layers in proportion to per-pillar weights; a weight of zero is a pinch-out
// (the layer has no thickness at that pillar). The weights are evaluated one pillar at a time
// from a layered field, so a block of the model needs no whole-model array.
#include <vector>

#include "deterministic_random.h"
#include "generator_parameters.h"
#include "model_frame.h"
#include "smooth_field.h"

namespace cutaway::generators {

class Layering {
public:
    /// clamp(NZ / 5, 1, 4) zones of near-equal layer counts; pinch-outs placed in correlated
    /// patches so that about `pinch_out_fraction` of the cells have all four pillar edges pinched.
    /// Every zone keeps at least one layer with thickness at every pillar.
    Layering(const GeneratorParameters& parameters, const ModelFrame& frame, DeterministicRandom& random);

    /// first_layer()[z] .. first_layer()[z+1]-1 are zone z's layers; size zones + 1, last = NZ.
    const std::vector<int>& first_layer() const { return first_layer_; }
    int zones() const { return int(first_layer_.size()) - 1; }
    /// Weights of every layer (NZ values, 0 where the layer pinches out) at pillar (pi, pj).
    void pillar_weights(int pi, int pj, std::vector<float>& weights) const;

private:
    std::vector<int> first_layer_;
    LayeredField field_;  ///< at the pillars: (NX+1) x (NY+1) x NZ
    float threshold_;     ///< field values below it pinch
};

}  // namespace cutaway::generators
