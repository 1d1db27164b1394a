#include "cone_test_scenes.h"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <random>

namespace cutaway::cone_field::testing {
namespace {

/// Uniform in [low, high), the same on every standard library (std distributions are not).
float uniform(std::mt19937& rng, float low, float high) {
    return low + (high - low) * float(double(rng()) / 4294967296.0);
}

/// Uniform integer in [low, high].
int uniform_int(std::mt19937& rng, int low, int high) { return low + int(rng() % std::uint32_t(high - low + 1)); }

}  // namespace

SeedImage scattered_seeds(int width, int height, int count, float min_depth, float max_depth, std::uint32_t rng_seed) {
    std::mt19937 rng(rng_seed);
    SeedImage seeds(width, height);
    count = std::min(count, width * height);
    for (int placed = 0; placed < count;) {
        const int x = uniform_int(rng, 0, width - 1);
        const int y = uniform_int(rng, 0, height - 1);
        if (seeds.has_seed(x, y)) continue;
        seeds.set_seed(x, y, uniform(rng, min_depth, max_depth));
        ++placed;
    }
    return seeds;
}

SeedImage block_seeds(int width, int height, int count, int max_side, float min_depth, float max_depth,
                      std::uint32_t rng_seed) {
    std::mt19937 rng(rng_seed);
    SeedImage seeds(width, height);
    for (int block = 0; block < count; ++block) {
        const int side_x = uniform_int(rng, 3, max_side);
        const int side_y = uniform_int(rng, 3, max_side);
        const int x0 = uniform_int(rng, 0, std::max(0, width - side_x));
        const int y0 = uniform_int(rng, 0, std::max(0, height - side_y));
        // A tilt of at most 10% of the depth range across the block keeps the plane inside the range.
        const float range = max_depth - min_depth;
        const float centre = uniform(rng, min_depth + 0.1f * range, max_depth - 0.1f * range);
        const float tilt_x = uniform(rng, -0.05f, 0.05f) * range / float(side_x);
        const float tilt_y = uniform(rng, -0.05f, 0.05f) * range / float(side_y);
        for (int y = y0; y < std::min(height, y0 + side_y); ++y) {
            for (int x = x0; x < std::min(width, x0 + side_x); ++x) {
                const float depth = centre + tilt_x * float(x - x0 - side_x / 2) + tilt_y * float(y - y0 - side_y / 2);
                if (!seeds.has_seed(x, y) || depth < seeds.depth.at(x, y)) seeds.set_seed(x, y, depth);
            }
        }
    }
    return seeds;
}

std::vector<ConeScene> jfa_test_scenes() {
    std::vector<ConeScene> scenes;
    // Jump flooding goes wrong where many cones meet: the dense scene (11% of the pixels are
    // seeds) is the hard one, the sparse one checks that few seeds stay exact.
    scenes.push_back({"scattered_300", scattered_seeds(512, 512, 300, 0.0f, 256.0f, 11)});
    scenes.push_back({"scattered_30000", scattered_seeds(512, 512, 30000, 0.0f, 256.0f, 12)});
    scenes.push_back({"blocks_40", block_seeds(512, 512, 40, 40, 0.0f, 256.0f, 13)});
    return scenes;
}

std::int64_t ulp_distance(float a, float b) {
    return std::abs(std::int64_t(std::bit_cast<std::int32_t>(a)) - std::int64_t(std::bit_cast<std::int32_t>(b)));
}

}  // namespace cutaway::cone_field::testing
