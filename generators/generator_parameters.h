#pragma once
// Every knob of the synthetic faulted corner-point generator, with units, defaults and checks.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "grid/grid_dims.h"
#include "grid/primary_selection.h"

namespace cutaway::generators {

/// A closed interval [first, second].
using Range = std::pair<double, double>;

struct GeneratorParameters {
    std::string name = "custom";      ///< preset name, or "custom"
    grid::GridDims dims{30, 50, 5};    ///< cells
    double length_x = 3000;            ///< model extent east, metres
    double length_y = 5000;            ///< model extent north, metres
    double thickness = 100;            ///< mean reservoir thickness (top to base), metres
    double top_depth = 2000;           ///< mean depth of the top horizon, metres (z down)
    std::uint64_t seed = 1;

    int fault_count = 3;
    Range throw_range{5, 30};          ///< vertical fault throw, metres; each fault draws one
    double fault_dip_deg = 70;         ///< angle from horizontal; 90 = vertical (untilted pillars)
    double fault_azimuth_deg = 30;     ///< mean strike, degrees clockwise from north
    double fault_azimuth_spread_deg = 20;  ///< each fault's strike within mean +- spread
    int lean_spread_pillars = 2;       ///< pillars beside a fault trace share its lean, fading out

    double horizon_roughness = 8;      ///< standard deviation of horizon relief, metres
    double pinch_out_fraction = 0.02;  ///< share of cells pinched to zero thickness (made inactive)
    double inactive_fraction = 0.05;   ///< share of cells made inactive in clusters

    double poro_mean = 0.2;
    double poro_std = 0.05;
    double poro_correlation_length = 500;  ///< lateral correlation length, metres

    int time_steps = 6;                ///< SWAT time steps (0: no saturation)
    int injector_count = 2;            ///< injector columns the water front starts from
};

/// Human-readable `key = value` lines for the file header, one per parameter.
std::vector<std::string> describe(const GeneratorParameters& parameters);

/// Bytes the generator holds at its peak for `parameters` (arrays it allocates, with margins).
std::size_t estimated_peak_bytes(const GeneratorParameters& parameters);
/// The same for generating only the cells of `box` (generate_block: no SWAT).
std::size_t estimated_peak_bytes(const GeneratorParameters& parameters, const grid::IjkBox& box);

/// Throws std::invalid_argument naming the parameter, its value and the allowed range, when the
/// parameters cannot give a model, or would need more than `memory_limit_bytes`.
void validate(const GeneratorParameters& parameters, std::size_t memory_limit_bytes);
/// The same for generating only the cells of `box` (whole-model indices, within the grid).
void validate(const GeneratorParameters& parameters, std::size_t memory_limit_bytes, const grid::IjkBox& box);

}  // namespace cutaway::generators
