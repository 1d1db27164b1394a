// Same parameters and seed give a byte-identical file; another seed gives another model.
#include <gtest/gtest.h>
#include <omp.h>

#include "generator_test_support.h"
#include "generators/deterministic_random.h"

namespace cutaway::generators {
namespace {

TEST(GeneratorDeterminism, SameSeedSameBytes) {
    const GeneratorParameters p = testing::small_parameters();
    const std::string first = testing::grdecl_text(p);
    const std::string second = testing::grdecl_text(p);
    ASSERT_GT(first.size(), 10000u);
    EXPECT_TRUE(first == second) << "two runs with seed " << p.seed << " differ";
}

// The pillar columns, cell checks and rock properties run on every core (OpenMP): one thread and
// four (more than this machine's cores, so the work is split whatever the machine) give the
// same bytes, including the report's counts in the header.
TEST(GeneratorDeterminism, OneThreadAndFourGiveTheSameBytes) {
    const GeneratorParameters p = testing::small_parameters();
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const std::string one = testing::grdecl_text(p);
    omp_set_num_threads(4);
    const std::string four = testing::grdecl_text(p);
    omp_set_num_threads(threads);
    ASSERT_GT(one.size(), 10000u);
    EXPECT_TRUE(one == four) << "1 and 4 threads differ for seed " << p.seed;
}

TEST(GeneratorDeterminism, OtherSeedOtherModel) {
    GeneratorParameters p = testing::small_parameters();
    const std::string first = testing::grdecl_text(p);
    p.seed += 1;
    EXPECT_NE(first, testing::grdecl_text(p));
}

TEST(GeneratorDeterminism, HeaderNamesEveryParameter) {
    const std::string text = testing::grdecl_text(testing::small_parameters());
    for (const char* key : {"dims = 24 30 6", "extent_m = 2400 3000 60", "seed = 1", "faults = 3", "throw_range_m = 5 30",
                            "fault_dip_deg = 70", "fault_azimuth_deg = 30", "horizon_roughness_m = 8",
                            "pinch_out_fraction = 0.02", "inactive_fraction = 0.05", "poro_mean = 0.2",
                            "poro_std = 0.05", "poro_correlation_length_m = 800", "time_steps = 6", "active_cells = "})
        EXPECT_NE(text.find(std::string("-- ") + key), std::string::npos) << key;
}

TEST(DeterministicRandom, NormalHasUnitMomentsAndFixedValues) {
    DeterministicRandom random(42, 7);
    double sum = 0, sum_sq = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double v = random.normal();
        sum += v;
        sum_sq += v * v;
    }
    EXPECT_NEAR(sum / n, 0.0, 0.01);
    EXPECT_NEAR(sum_sq / n, 1.0, 0.01);
    // Our own formulas on mt19937_64 bits: the same value on every standard library.
    DeterministicRandom a(42, 7), b(42, 7), c(42, 8);
    EXPECT_EQ(a.uniform01(), b.uniform01());
    EXPECT_NE(DeterministicRandom(42, 7).uniform01(), c.uniform01());
}

}  // namespace
}  // namespace cutaway::generators
