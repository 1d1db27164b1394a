#pragma once
// Seed images the cone-field tests share: reproducible from a name and an RNG seed.
#include <cstdint>
#include <string>
#include <vector>

#include "cone_field/cone_image.h"

namespace cutaway::cone_field::testing {

/// `count` seed pixels at random distinct positions, depths uniform in [min_depth, max_depth).
SeedImage scattered_seeds(int width, int height, int count, float min_depth, float max_depth, std::uint32_t rng_seed);

/// `count` random rectangles (sides 3..max_side pixels), each a tilted plane of depth in
/// [min_depth, max_depth) over its pixels, the nearer plane kept where they overlap: the shape of
/// the primaries' rear hull rendered into a seed buffer.
SeedImage block_seeds(int width, int height, int count, int max_side, float min_depth, float max_depth,
                      std::uint32_t rng_seed);

/// A named scene for parameterised tests.
struct ConeScene {
    std::string name;
    SeedImage seeds;
};

/// The 512 x 512 scenes the jump flooding accuracy tests run on, depths in [0, 256).
std::vector<ConeScene> jfa_test_scenes();

/// Distance in units in the last place between two non-negative finite floats.
std::int64_t ulp_distance(float a, float b);

}  // namespace cutaway::cone_field::testing
