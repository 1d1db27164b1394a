// frustum-clusters: the IJK boxes it merges primaries into (primary_clusters.h) cover every
// primary exactly once and hold nothing else; fewer boxes than primaries where primaries touch.
// Its exposure (1.0 on random scenes) is checked with every strategy in cut_strategies_gl_test.cpp.
#include <gtest/gtest.h>

#include <random>

#include "cutaway/cut_surface/primary_clusters.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

TEST(PrimaryClusters, BoxesCoverEveryPrimaryOnceAndNothingElse) {
    const grid::GridDims& d = petra().dims();
    std::mt19937 random(5);
    for (int trial = 0; trial < 10; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const std::vector<std::uint8_t> flags = random_primaries(petra(), random);
        std::vector<int> covered(flags.size(), 0);
        const std::vector<pipeline::IjkCellBox> boxes = pipeline::primary_boxes(flags, d);
        for (const pipeline::IjkCellBox& b : boxes) {
            ASSERT_TRUE(b.i0 <= b.i1 && b.j0 <= b.j1 && b.k0 <= b.k1 && b.i0 >= 0 && b.i1 < d.nx && b.j1 < d.ny && b.k1 < d.nz);
            for (int k = b.k0; k <= b.k1; ++k)
                for (int j = b.j0; j <= b.j1; ++j)
                    for (int i = b.i0; i <= b.i1; ++i) ++covered[std::size_t(i + d.nx * (j + d.ny * k))];
        }
        std::size_t primaries = 0;
        for (std::size_t cell = 0; cell < flags.size(); ++cell) {
            primaries += flags[cell] ? 1 : 0;
            ASSERT_EQ(covered[cell], flags[cell] ? 1 : 0) << "cell " << cell;
        }
        EXPECT_LE(boxes.size(), primaries);
    }
}

TEST(PrimaryClusters, ASolidBlockIsOneBox) {
    const grid::GridDims d{6, 5, 4};
    std::vector<std::uint8_t> flags(d.cell_count(), 0);
    for (int k = 1; k <= 2; ++k)
        for (int j = 1; j <= 3; ++j)
            for (int i = 2; i <= 4; ++i) flags[std::size_t(i + d.nx * (j + d.ny * k))] = 1;
    const std::vector<pipeline::IjkCellBox> boxes = pipeline::primary_boxes(flags, d);
    ASSERT_EQ(boxes.size(), 1u);
    EXPECT_EQ(boxes[0].i0, 2);
    EXPECT_EQ(boxes[0].i1, 4);
    EXPECT_EQ(boxes[0].j0, 1);
    EXPECT_EQ(boxes[0].j1, 3);
    EXPECT_EQ(boxes[0].k0, 1);
    EXPECT_EQ(boxes[0].k1, 2);
}

TEST(PrimaryClusters, RefusesFlagsOfTheWrongSize) {
    EXPECT_THROW(pipeline::primary_boxes(std::vector<std::uint8_t>(5, 1), grid::GridDims{2, 2, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace cutaway::test
