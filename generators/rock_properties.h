#pragma once
// Static rock properties per cell: PORO (layered, spatially correlated), FACIES from PORO,
// PERMX from PORO and FACIES (log-linear), NTG from PORO.
#include <cstdint>
#include <vector>

#include "deterministic_random.h"
#include "generator_parameters.h"
#include "model_frame.h"

namespace cutaway::generators {

struct RockProperties {
    std::vector<float> poro;            ///< fraction, NX*NY*NZ
    std::vector<float> permx;           ///< mD, NX*NY*NZ
    std::vector<float> ntg;             ///< fraction, NX*NY*NZ
    std::vector<std::int32_t> facies;   ///< 1 shale, 2 sand, 3 clean sand, NX*NY*NZ
};

/// PORO = mean + std * (correlated field + a per-layer shift), clipped to [0.01, 0.45 or above
/// the mean]; correlation `poro_correlation_length` laterally, 0.7 between adjacent layers.
RockProperties make_rock_properties(const GeneratorParameters& parameters, const ModelFrame& frame,
                                    DeterministicRandom& random);

}  // namespace cutaway::generators
