#pragma once
// Parameters of the synthetic seismic cube, its named sizes (the paper's cubes and the growth
// series of its figure 8) and their validation.
#include <cstdint>
#include <string>
#include <vector>

namespace cutaway::generators {

struct SeismicParameters {
    std::string name = "custom";
    int inlines = 101;
    int crosslines = 101;
    int samples = 250;
    std::uint64_t seed = 1;
    int sample_interval_us = 4000;   ///< microseconds between samples
    int horizons = 24;               ///< reflecting layer boundaries (> 0)
    int faults = 3;                  ///< normal faults cutting the layers (0..16)
    double max_throw_samples = 12;   ///< largest fault throw, in time samples
    double fault_dip_deg = 70;       ///< fault dip from horizontal, 30..90 degrees
    double horizon_relief_samples = 8;  ///< amplitude of the horizons' lateral undulation, samples
    double ricker_peak_hz = 30;      ///< Ricker wavelet peak frequency, hertz
    double noise_fraction = 0.05;    ///< Gaussian noise std relative to the signal's RMS, >= 0
};

/// The paper's cubes: "paper-500" (101x101x500) and "paper-250" (101x101x250), plus the growth
/// series "growth-1" .. "growth-10" (step k: k * (10 x 28 x 25) samples, figure 8).
std::vector<SeismicParameters> seismic_presets();

/// The preset named `name`; throws std::invalid_argument listing the names if there is none.
SeismicParameters find_seismic_preset(const std::string& name);

/// Dimensions (inlines, crosslines, samples) of growth step `step` (1..10) of figure 8.
SeismicParameters growth_step(int step);

/// Throws std::invalid_argument naming the first bad field and the range expected; also refuses
/// cubes whose samples would exceed `memory_limit_bytes`.
void validate(const SeismicParameters& parameters, std::uint64_t memory_limit_bytes);

}  // namespace cutaway::generators
