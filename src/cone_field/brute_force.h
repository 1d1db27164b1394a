#pragma once
// Exact cone-field cut by brute force: every pixel against every seed, O(pixels x seeds).
// Runs on the CPU: it is the definition written as code, the oracle the exact reference is tested
// against on small images; far too slow for full frames.
#include "cone_field/cone_image.h"

namespace cutaway::cone_field {

/// d(p) = max(0, max over seeds q of (z(q) - m |q - p|)) for every pixel, m = slope_per_pixel
/// (depth units per pixel). Output: the seed image's size, depth units, 0 where no cone reaches.
/// Throws std::invalid_argument for a malformed seed image or a slope that is not positive.
FloatImage brute_force_cut(const SeedImage& seeds, double slope_per_pixel);

}  // namespace cutaway::cone_field
