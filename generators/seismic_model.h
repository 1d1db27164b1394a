#pragma once
// Synthetic post-stack seismic: layered reflectivity cut by normal faults, convolved with a Ricker
// wavelet, plus Gaussian noise. Same parameters and seed give the same cube on every platform.
#include <cstdint>

#include "generators/seismic_parameters.h"
#include "generators/seismic_volume.h"

namespace cutaway::generators {

/// Default refusal threshold for the cube's float samples (bytes).
inline constexpr std::uint64_t kDefaultSeismicMemoryLimit = std::uint64_t(4) << 30;

/// Ricker wavelet value at `time_s` seconds from its centre for peak frequency `peak_hz`:
/// (1 - 2 pi^2 f^2 t^2) exp(-pi^2 f^2 t^2); 1 at t = 0.
double ricker(double peak_hz, double time_s);

/// The cube described by `parameters` (validated first; throws std::invalid_argument).
SeismicVolume generate_seismic(const SeismicParameters& parameters,
                               std::uint64_t memory_limit_bytes = kDefaultSeismicMemoryLimit);

}  // namespace cutaway::generators
