#pragma once
// SWAT over time: water injected in a few columns spreads as a front whose arrival time at a
// cell is the shortest travel time through active neighbours (Dijkstra), faster through high
// permeability. Behind the front the saturation rises towards 1 - Sor; a SWAT range just above
// the front saturation therefore selects a band that moves outwards step by step.
#include <cstdint>
#include <vector>

#include "deterministic_random.h"
#include "generator_parameters.h"
#include "model_frame.h"

namespace cutaway::generators {

struct SaturationModel {
    static constexpr float connate = 0.15f;   ///< Swi: ahead of the front
    static constexpr float front = 0.55f;     ///< saturation just behind the front (shock)
    static constexpr float residual_oil = 0.2f;  ///< Sor: water never exceeds 1 - Sor
};

struct WaterFlood {
    std::vector<std::vector<float>> steps;  ///< time_steps arrays of NX*NY*NZ SWAT values
    std::vector<grid::CellIjk> injectors;   ///< column (i, j) of each injector, k = 0
    std::vector<double> swept_fraction;     ///< per step, share of active cells behind the front
};

/// `mean_layer_thickness`: metres; `actnum`, `permx` (mD): per cell. The last step's front has
/// swept 80% of the cells the injectors reach.
WaterFlood make_water_flood(const GeneratorParameters& parameters, const ModelFrame& frame,
                            double mean_layer_thickness, const std::vector<std::uint8_t>& actnum,
                            const std::vector<float>& permx, DeterministicRandom& random);

}  // namespace cutaway::generators
