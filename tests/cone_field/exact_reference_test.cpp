// The exact reference equals brute force, and its pruning skips most seed-pixel pairs.
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <random>

#include "cone_test_scenes.h"
#include "cone_field/brute_force.h"
#include "cone_field/cone_slope.h"
#include "cone_field/exact_reference.h"

namespace cutaway::cone_field {
namespace {

using testing::block_seeds;
using testing::scattered_seeds;

// Both evaluate every cone through cone_height in double and take a max, which does not depend on
// the order; pruning only skips seeds whose rounded bound already cannot win. So the images should
// agree bit for bit. A few ulps of slack would only absorb a compiler contracting a*b+c into an
// FMA in one loop and not the other (legal under -ffp-contract); more than that is a real bug.
constexpr std::int64_t max_ulps = 4;

std::int64_t max_ulp_difference(const FloatImage& a, const FloatImage& b) {
    std::int64_t worst = 0;
    for (std::size_t i = 0; i < a.pixel_count(); ++i) {
        worst = std::max(worst, testing::ulp_distance(a.pixels[i], b.pixels[i]));
    }
    return worst;
}

std::vector<testing::ConeScene> small_cases() {
    std::vector<testing::ConeScene> cases;
    cases.push_back({"empty", SeedImage(23, 17)});
    SeedImage single(40, 31);
    single.set_seed(7, 25, 30.0f);
    cases.push_back({"single_seed", single});
    SeedImage one_pixel(1, 1);
    one_pixel.set_seed(0, 0, 5.0f);
    cases.push_back({"one_pixel", one_pixel});
    cases.push_back({"single_row", scattered_seeds(97, 1, 9, 0.0f, 50.0f, 1)});
    cases.push_back({"sparse_1_percent", scattered_seeds(61, 45, 27, 0.0f, 100.0f, 2)});
    cases.push_back({"ten_percent", scattered_seeds(64, 64, 410, 0.0f, 100.0f, 3)});
    cases.push_back({"half_full", scattered_seeds(50, 37, 925, -20.0f, 100.0f, 4)});  // some seeds behind the camera
    cases.push_back({"full", scattered_seeds(33, 29, 33 * 29, 0.0f, 100.0f, 5)});
    cases.push_back({"blocks", block_seeds(80, 60, 6, 15, 10.0f, 90.0f, 6)});
    return cases;
}

TEST(ExactReference, EqualsBruteForceOnSmallImages) {
    std::int64_t worst_ulps = 0;
    for (const testing::ConeScene& c : small_cases()) {
        for (const double slope : {0.05, 0.5, 2.0, 10.0}) {
            const FloatImage brute = brute_force_cut(c.seeds, slope);
            for (const unsigned threads : {1u, 2u, 3u}) {
                for (const int tile : {1, 5, 16}) {
                    const ExactReferenceResult exact = exact_reference_cut(c.seeds, slope, {threads, tile});
                    ASSERT_EQ(exact.cut.width, brute.width);
                    ASSERT_EQ(exact.cut.height, brute.height);
                    const std::int64_t ulps = max_ulp_difference(exact.cut, brute);
                    worst_ulps = std::max(worst_ulps, ulps);
                    EXPECT_LE(ulps, max_ulps) << c.name << " m=" << slope << " threads=" << threads << " tile=" << tile;
                }
            }
        }
    }
    std::cout << "exact reference vs brute force: largest difference " << worst_ulps << " ulps\n";
}

TEST(ExactReference, SingleSeedIsAnExactCone) {
    SeedImage seeds(31, 31);
    seeds.set_seed(10, 20, 12.0f);
    const FloatImage cut = exact_reference_cut(seeds, 1.5).cut;
    for (int y = 0; y < 31; ++y) {
        for (int x = 0; x < 31; ++x) {
            const double expected = std::max(0.0, 12.0 - 1.5 * std::hypot(x - 10, y - 20));
            EXPECT_NEAR(cut.at(x, y), expected, 1e-5) << x << "," << y;  // float output of depth <= 12
        }
    }
}

// Blocks of seeds (the primaries' rear hull) with depths close together: each pixel is decided
// by a few seed tiles, the rest is pruned.
TEST(ExactReference, PruningSkipsMostPairsOnAStructuredScene) {
    const SeedImage seeds = block_seeds(256, 256, 12, 30, 100.0f, 200.0f, 21);
    const std::size_t seed_count = collect_seeds(seeds).size();
    const ExactReferenceResult exact = exact_reference_cut(seeds, 1.0, {2, 16});
    const double brute_pairs = double(seeds.depth.pixel_count()) * double(seed_count);
    const double evaluated_share = double(exact.evaluated_pairs) / brute_pairs;
    std::cout << "pruning: " << seed_count << " seeds, " << exact.evaluated_pairs << " pairs evaluated of "
              << brute_pairs << " (" << 100.0 * evaluated_share << "%)\n";
    ::testing::Test::RecordProperty("evaluated_pair_share", std::to_string(evaluated_share));
    EXPECT_LT(evaluated_share, 0.05);
}

TEST(ExactReference, ThreadCountAndTileSizeDoNotChangeTheResult) {
    const SeedImage seeds = block_seeds(200, 150, 10, 25, 20.0f, 120.0f, 8);
    const ExactReferenceResult one = exact_reference_cut(seeds, 0.7, {1, 16});
    const ExactReferenceResult many = exact_reference_cut(seeds, 0.7, {4, 7});
    EXPECT_EQ(one.threads_used, 1u);
    EXPECT_EQ(many.threads_used, 4u);
    EXPECT_EQ(max_ulp_difference(one.cut, many.cut), 0);
}

// Full HD with thousands to tens of thousands of seeds: the time is printed for the record (about
// 0.2 to 0.6 s on 2 cores in Release; no time limit asserted on a shared machine), and sampled
// pixels are checked against the brute-force maximum over all seeds.
TEST(ExactReference, FullHdFrameMatchesBruteForceAtSampledPixels) {
    struct Frame {
        const char* name;
        SeedImage seeds;
        double slope;
    };
    const Frame frames[] = {
        {"scattered_5000", scattered_seeds(1920, 1080, 5000, 0.0f, 1000.0f, 31), 0.5},
        {"blocks_400", block_seeds(1920, 1080, 400, 24, 50.0f, 150.0f, 32), 0.25},
    };
    for (const Frame& frame : frames) {
        const std::vector<Seed> seed_list = collect_seeds(frame.seeds);
        const auto start = std::chrono::steady_clock::now();
        const ExactReferenceResult exact = exact_reference_cut(frame.seeds, frame.slope);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cout << "full HD exact " << frame.name << ": " << seed_list.size() << " seeds, m=" << frame.slope << ", "
                  << exact.threads_used << " threads: " << seconds << " s, "
                  << double(exact.evaluated_pairs) / double(frame.seeds.depth.pixel_count()) << " pairs per pixel\n";
        ::testing::Test::RecordProperty(std::string(frame.name) + " seconds", std::to_string(seconds));
        std::mt19937 rng(5);
        for (int sample = 0; sample < 300; ++sample) {
            const int x = int(rng() % 1920u);
            const int y = int(rng() % 1080u);
            double best = 0.0;
            for (const Seed& seed : seed_list) {
                best = std::max(best, cone_height(seed.depth, frame.slope, seed.x - x, seed.y - y));
            }
            ASSERT_LE(testing::ulp_distance(exact.cut.at(x, y), float(best)), max_ulps)
                << frame.name << " " << x << "," << y;
        }
    }
}

}  // namespace
}  // namespace cutaway::cone_field
