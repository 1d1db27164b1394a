// PORO statistics and correlation, PERMX/NTG/FACIES derived from PORO, and a SWAT front that
// moves away from the injectors step by step.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "generator_test_support.h"
#include "generators/water_saturation.h"

namespace cutaway::generators {
namespace {

TEST(RockProperties, PorosityMatchesMeanStdAndIsCorrelated) {
    GeneratorParameters p = testing::small_parameters();
    p.dims = {60, 60, 8};
    p.length_x = p.length_y = 6000;
    p.poro_correlation_length = 1000;  // 10 cells
    const GeneratedModel model = testing::generate_quietly(p);
    const std::vector<float>& poro = *model.grid.property("PORO");
    double sum = 0, sum_sq = 0;
    for (float v : poro) {
        sum += v;
        sum_sq += double(v) * v;
    }
    const double mean = sum / double(poro.size()), std = std::sqrt(sum_sq / double(poro.size()) - mean * mean);
    EXPECT_NEAR(mean, p.poro_mean, 0.02);
    EXPECT_NEAR(std, p.poro_std, 0.02);
    // Correlation of lateral neighbours at lag 1 cell (high) and lag 30 cells (low).
    auto correlation = [&](int lag) {
        double s = 0;
        std::size_t n = 0;
        const grid::GridDims& d = p.dims;
        for (int k = 0; k < d.nz; ++k)
            for (int j = 0; j < d.ny; ++j)
                for (int i = 0; i + lag < d.nx; ++i, ++n)
                    s += (poro[d.cell_index(i, j, k)] - mean) * (poro[d.cell_index(i + lag, j, k)] - mean);
        return s / double(n) / (std * std);
    };
    EXPECT_GT(correlation(1), 0.8);
    EXPECT_LT(correlation(30), 0.4);
}

TEST(RockProperties, DerivedPropertiesFollowPorosity) {
    const GeneratedModel model = testing::generate_quietly(testing::small_parameters());
    const std::vector<float>& poro = *model.grid.property("PORO");
    const std::vector<float>& perm = *model.grid.property("PERMX");
    const std::vector<float>& ntg = *model.grid.property("NTG");
    const std::vector<std::int32_t>& facies = *model.grid.int_property("FACIES");
    for (std::size_t c = 0; c < poro.size(); ++c) {
        ASSERT_TRUE(facies[c] >= 1 && facies[c] <= 3);
        ASSERT_GT(perm[c], 0);
        ASSERT_TRUE(ntg[c] >= 0.05f && ntg[c] <= 1.0f);
        for (std::size_t o = c + 1; o < std::min(poro.size(), c + 50); ++o) {
            if (facies[o] == facies[c] && poro[o] > poro[c]) {
                ASSERT_GE(perm[o], perm[c]);
            }
        }
    }
}

TEST(WaterSaturation, FrontBandMovesAwayFromInjectors) {
    GeneratorParameters p = testing::small_parameters();
    p.injector_count = 1;
    const GeneratedModel model = testing::generate_quietly(p);
    const grid::CornerPointGrid& g = model.grid;
    const grid::GridDims& d = g.dims();
    ASSERT_EQ(g.step_count("SWAT"), std::size_t(p.time_steps));
    ASSERT_EQ(model.report.injectors.size(), 1u);
    int inj_i = 0, inj_j = 0;
    ASSERT_EQ(std::sscanf(model.report.injectors[0].c_str(), "%d %d", &inj_i, &inj_j), 2);

    double previous_distance = -1, previous_swept = -1;
    for (std::size_t step = 0; step < g.step_count("SWAT"); ++step) {
        const std::vector<float>& swat = *g.dynamic_property("SWAT", step);
        // The band just behind the front: the range a user would select.
        double distance = 0;
        std::size_t band = 0, swept = 0;
        for (std::size_t c = 0; c < swat.size(); ++c) {
            if (!g.active(c)) continue;
            swept += swat[c] > SaturationModel::connate;
            if (swat[c] < SaturationModel::front || swat[c] > SaturationModel::front + 0.08f) continue;
            const grid::CellIjk ijk = grid::cell_ijk(d, c);
            distance += std::hypot(ijk.i - inj_i, ijk.j - inj_j);
            ++band;
        }
        ASSERT_GT(band, 0u) << "step " << step;
        EXPECT_GT(distance / double(band), previous_distance) << "step " << step;
        EXPECT_GT(double(swept), previous_swept) << "step " << step;
        previous_distance = distance / double(band);
        previous_swept = double(swept);
    }
}

}  // namespace
}  // namespace cutaway::generators
