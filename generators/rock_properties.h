#pragma once
// Static rock properties per cell: PORO (layered, spatially correlated), FACIES from PORO,
// PERMX from PORO and FACIES (log-linear), NTG from PORO.
#include <cstdint>
#include <vector>

#include "deterministic_random.h"
#include "grid/primary_selection.h"
#include "generator_parameters.h"
#include "model_frame.h"

namespace cutaway::generators {

struct RockProperties {
    std::vector<float> poro;            ///< fraction, one per cell of the box
    std::vector<float> permx;           ///< mD
    std::vector<float> ntg;             ///< fraction
    std::vector<std::int32_t> facies;   ///< 1 shale, 2 sand, 3 clean sand
};

/// PORO = mean + std * (correlated field + a per-layer shift), clipped to [0.01, 0.45 or above
/// the mean]; correlation `poro_correlation_length` laterally, 0.7 between adjacent layers. For
/// the cells of `box` (whole-model indices), in Eclipse order within it.
RockProperties make_rock_properties(const GeneratorParameters& parameters, const ModelFrame& frame,
                                    DeterministicRandom& random, const grid::IjkBox& box);

}  // namespace cutaway::generators
