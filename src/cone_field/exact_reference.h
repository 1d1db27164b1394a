#pragma once
// Exact cone-field cut with exact pruning, multithreaded. Runs on the CPU: it is the reference the
// other strategies (frustum union, chamfer, jump flooding) are measured against in tests and
// experiments, not a per-frame strategy. Equal to brute_force_cut bit for bit, but full frames
// (1920 x 1080 with thousands of seeds) take seconds instead of hours.
//
// Pruning: pixels and seeds are grouped into square tiles. A seed tile keeps the bounding box of
// its seeds and its largest depth; since a cone never rises with distance, that depth minus m
// times the gap between the boxes bounds every height the tile can give anywhere in a pixel tile
// (and, with the gap to one pixel, at that pixel). Seed tiles are visited best bound first and
// skipped, for a tile or a pixel, once the bound cannot beat the best height found so far. The
// bound goes through the same rounded double operations as the heights (all monotone), so a
// skipped seed could never have changed the result.
#include <cstdint>

#include "cone_field/cone_image.h"

namespace cutaway::cone_field {

struct ExactReferenceOptions {
    unsigned thread_count = 0;  ///< worker threads (std::thread); 0 = std::thread::hardware_concurrency()
    int tile_size = 16;         ///< side of the pixel and seed tiles, pixels, 1..1024
};

struct ExactReferenceResult {
    FloatImage cut;                     ///< the seed image's size, depth units, 0 where no cone reaches
    std::uint64_t evaluated_pairs = 0;  ///< cone heights computed; brute force computes pixels x seeds
    unsigned threads_used = 0;
};

/// d(p) = max(0, max over seeds q of (z(q) - m |q - p|)) for every pixel, m = slope_per_pixel
/// (depth units per pixel). Throws std::invalid_argument for a malformed seed image, a slope that
/// is not positive, more than 1024 threads or a tile size outside 1..1024.
ExactReferenceResult exact_reference_cut(const SeedImage& seeds, double slope_per_pixel,
                                         const ExactReferenceOptions& options = {});

}  // namespace cutaway::cone_field
