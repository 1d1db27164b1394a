// Chamfer propagation: two passes give exactly the mask's path length, and the slope error of a
// single cone stays within the mask's theoretical bounds in every direction.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "cone_field/chamfer.h"

namespace cutaway::cone_field {
namespace {

// Length of the shortest path of mask steps from the origin to (x, y), pixels.
// 3x3 with steps a (edge) and b (diagonal): for 0 <= y <= x, (x - y) a + y b.
// 5x5 adds the knight step c = (2, 1): for 0 <= y <= x/2, (x - 2y) a + y c;
// for x/2 <= y <= x, (x - y) c + (2y - x) b (knights and diagonals).
double chamfer_length(ChamferMask mask, int x, int y) {
    x = std::abs(x);
    y = std::abs(y);
    if (y > x) std::swap(x, y);
    switch (mask) {
    case ChamferMask::city_diagonal_3x3: return (x - y) + std::sqrt(2.0) * y;
    case ChamferMask::borgefors_3x3: return (x - y) + 4.0 / 3.0 * y;
    case ChamferMask::borgefors_5x5: return 2 * y <= x ? (x - 2 * y) + 2.2 * y : 2.2 * (x - y) + 1.4 * (2 * y - x);
    case ChamferMask::chessboard_3x3: return x;  // max(|x|, |y|)
    }
    return 0.0;
}

// Relative length error L_chamfer / L_euclid - 1 over directions 0..45 degrees (the rest follow by
// symmetry), with t = tan(angle):
// (1, sqrt2): sqrt2-1 ... (1 - t + sqrt2 t) / sqrt(1 + t^2) has its maximum sqrt(4 - 2 sqrt2) at
//   t = sqrt2 - 1 (22.5 degrees) and its minimum 1 at 0 and 45 degrees: [0, +8.239%].
// <3,4>/3: (1 + t/3) / sqrt(1 + t^2): maximum sqrt(10)/3 at t = 1/3, minimum (4/3)/sqrt2 at 45
//   degrees: [-5.719%, +5.409%].
// <5,7,11>/5: for t <= 1/2, (1 + 0.2 t) / sqrt(1 + t^2): maximum sqrt(1.04) at t = 0.2; for
//   t >= 1/2, (0.8 + 0.6 t) / sqrt(1 + t^2): maximum 1 at t = 0.75; minimum 1.1 / sqrt(1.25) at
//   t = 1/2: [-1.613%, +1.980%].
struct SlopeBounds {
    ChamferMask mask;
    double low;
    double high;
};
const SlopeBounds slope_bounds[] = {
    {ChamferMask::city_diagonal_3x3, 0.0, std::sqrt(4.0 - 2.0 * std::sqrt(2.0)) - 1.0},
    {ChamferMask::borgefors_3x3, 4.0 / 3.0 / std::sqrt(2.0) - 1.0, std::sqrt(10.0) / 3.0 - 1.0},
    {ChamferMask::borgefors_5x5, 1.1 / std::sqrt(1.25) - 1.0, std::sqrt(1.04) - 1.0},
};

constexpr int radius = 150;          // pixels around the seed
constexpr double seed_depth = 1000;  // deep enough that the cone stays above 0 in the whole image
constexpr double slope = 2.0;

SeedImage centred_seed() {
    SeedImage seeds(2 * radius + 1, 2 * radius + 1);
    seeds.set_seed(radius, radius, float(seed_depth));
    return seeds;
}

TEST(Chamfer, TwoPassesGiveTheMaskPathLength) {
    const SeedImage seeds = centred_seed();
    for (const ChamferMask mask : {ChamferMask::city_diagonal_3x3, ChamferMask::borgefors_3x3, ChamferMask::borgefors_5x5,
                                   ChamferMask::chessboard_3x3}) {
        const FloatImage cut = chamfer_cut(seeds, slope, mask);
        for (int y = 0; y < cut.height; ++y) {
            for (int x = 0; x < cut.width; ++x) {
                const double expected = seed_depth - slope * chamfer_length(mask, x - radius, y - radius);
                // float output of depths up to 1000: half an ulp is 3e-5.
                ASSERT_NEAR(cut.at(x, y), expected, 1e-4) << chamfer_mask_name(mask) << " " << x << "," << y;
            }
        }
    }
}

TEST(Chamfer, SlopeErrorWithinTheoreticalBounds) {
    const SeedImage seeds = centred_seed();
    for (const SlopeBounds& bound : slope_bounds) {
        const FloatImage cut = chamfer_cut(seeds, slope, bound.mask);
        double lowest = 1.0;
        double highest = -1.0;
        for (int y = 0; y < cut.height; ++y) {
            for (int x = 0; x < cut.width; ++x) {
                const double distance = std::hypot(x - radius, y - radius);
                if (distance < 20.0) continue;  // close by, float rounding of the depth is a visible slope error
                const double recovered_slope = (seed_depth - cut.at(x, y)) / distance;
                const double error = recovered_slope / slope - 1.0;
                lowest = std::min(lowest, error);
                highest = std::max(highest, error);
            }
        }
        std::cout << chamfer_mask_name(bound.mask) << ": slope error " << 100.0 * lowest << "% .. " << 100.0 * highest
                  << "% (bounds " << 100.0 * bound.low << "% .. " << 100.0 * bound.high << "%)\n";
        ::testing::Test::RecordProperty(std::string(chamfer_mask_name(bound.mask)) + " slope_error_range",
                                        std::to_string(lowest) + " .. " + std::to_string(highest));
        // 1e-5: float rounding of depth 1000 (3e-5) over at least 20 pixels at slope 2.
        EXPECT_GE(lowest, bound.low - 1e-5) << chamfer_mask_name(bound.mask);
        EXPECT_LE(highest, bound.high + 1e-5) << chamfer_mask_name(bound.mask);
        // The bounds are reached, not just respected: lattice directions come within 0.05% of them.
        EXPECT_LE(lowest, bound.low + 5e-4) << chamfer_mask_name(bound.mask);
        EXPECT_GE(highest, bound.high - 5e-4) << chamfer_mask_name(bound.mask);
    }
}

}  // namespace
}  // namespace cutaway::cone_field
