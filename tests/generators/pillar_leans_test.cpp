// Leaning fault pillars never cross: where fault traces meet, the summed leans used to turn
// cells inside out (161 at 1M cells, 93,874 at 10M before the cap).
#include <gtest/gtest.h>

#include "generator_test_support.h"

namespace cutaway::generators {
namespace {

// Small lateral cells, many faults and large throws: the summed leans would make neighbouring
// pillars cross within the model's depth range, so the leans must be scaled down.
GeneratorParameters crossing_faults() {
    GeneratorParameters p = testing::small_parameters();
    p.dims = {60, 60, 8};
    p.length_x = 600;
    p.length_y = 600;
    p.fault_count = 8;
    p.throw_range = {20, 40};
    p.fault_dip_deg = 50;
    p.fault_azimuth_spread_deg = 90;
    p.lean_spread_pillars = 1;
    return p;
}

TEST(PillarLeans, CrossingFaultsAreScaledSoNoCellInverts) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        GeneratorParameters p = crossing_faults();
        p.seed = seed;
        const GeneratedModel model = testing::generate_quietly(p);
        EXPECT_LT(model.report.lean_scale, 1.0) << "seed " << seed << ": the cap was expected to engage";
        EXPECT_GT(model.report.lean_scale, 0.0);
        EXPECT_EQ(model.report.inverted_cells, 0u) << "seed " << seed;
        EXPECT_EQ(model.report.degenerate_cells, 0u) << "seed " << seed;
    }
}

TEST(PillarLeans, GentleFaultsKeepTheirFullLean) {
    // The zaphirus preset's 100 m cells leave room: its leans are not scaled.
    const GeneratedModel model = testing::generate_quietly(find_preset("zaphirus"));
    EXPECT_EQ(model.report.lean_scale, 1.0);
}

}  // namespace
}  // namespace cutaway::generators
