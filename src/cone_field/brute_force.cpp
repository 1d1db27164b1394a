#include "cone_field/brute_force.h"

#include <algorithm>

#include "cone_field/cone_slope.h"

namespace cutaway::cone_field {

FloatImage brute_force_cut(const SeedImage& seeds, double slope_per_pixel) {
    check_slope_per_pixel(slope_per_pixel);
    const std::vector<Seed> seed_list = collect_seeds(seeds);
    FloatImage cut(seeds.width(), seeds.height());
    for (int y = 0; y < cut.height; ++y) {
        for (int x = 0; x < cut.width; ++x) {
            double best = 0.0;
            for (const Seed& seed : seed_list) {
                best = std::max(best, cone_height(seed.depth, slope_per_pixel, seed.x - x, seed.y - y));
            }
            cut.at(x, y) = float(best);
        }
    }
    return cut;
}

}  // namespace cutaway::cone_field
