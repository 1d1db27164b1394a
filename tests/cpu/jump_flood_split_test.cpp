// The regions of a GPU jump flooding pass (cut_surface/jump_flood_split.h) cover every row of
// every column exactly once, with the blocks jump_flood.comp floods: an invocation's first row
// from block_start, and in a paired region that row and the one a step further, both inside.
#include <gtest/gtest.h>

#include <vector>

#include "cutaway/cut_surface/jump_flood_split.h"

namespace cutaway::test {
namespace {

/// jump_flood.comp's block_start: in a paired region invocation i covers row i + (i / step) * step.
int block_start(int invocation, bool paired, int step) { return paired ? invocation + invocation / step * step : invocation; }

TEST(JumpFloodSplit, EveryPixelFloodedExactlyOnce) {
    // Sizes (columns = texels of 2 pixels): powers of two, odd, smaller than a step, 1080p and 4K
    // (the experiments' sizes).
    const std::vector<std::pair<int, int>> sizes = {{1, 1}, {1, 3}, {4, 5}, {256, 512}, {151, 173}, {320, 360}, {960, 1080}, {1920, 2160}};
    for (const auto& [columns, rows] : sizes) {
        for (int step = 1; step <= 4096; step *= 2) {
            SCOPED_TRACE(std::to_string(columns) + "x" + std::to_string(rows) + " step " + std::to_string(step));
            std::vector<int> floods(std::size_t(columns) * std::size_t(rows), 0);
            std::size_t invocations = 0, cells_flooded = 0;
            for (const pipeline::JumpFloodRegion& region : pipeline::jump_flood_regions(columns, rows, step)) {
                ASSERT_EQ(region.invocations.x, columns);
                ASSERT_GT(region.invocations.y, 0);
                EXPECT_EQ(region.origin.x, 0);
                if (region.paired_y) {
                    EXPECT_EQ(region.origin.y, 0);
                }
                const int block_y = region.paired_y ? 2 : 1;
                invocations += std::size_t(region.invocations.x) * std::size_t(region.invocations.y);
                cells_flooded += std::size_t(region.invocations.x) * std::size_t(region.invocations.y) * std::size_t(block_y);
                for (int iy = 0; iy < region.invocations.y; ++iy)
                    for (int x = 0; x < region.invocations.x; ++x)
                        for (int by = 0; by < block_y; ++by) {
                            const int y = region.origin.y + block_start(iy, region.paired_y, step) + by * step;
                            ASSERT_TRUE(y >= 0 && y < rows) << "row " << y << " outside";
                            ++floods[std::size_t(y) * std::size_t(columns) + std::size_t(x)];
                        }
            }
            for (std::size_t i = 0; i < floods.size(); ++i) ASSERT_EQ(floods[i], 1) << "column " << i % std::size_t(columns) << ", row " << i / std::size_t(columns);
            EXPECT_EQ(cells_flooded, floods.size());
            if (rows >= 4 * step) {  // mostly whole spans: most blocks are 2 rows
                EXPECT_LE(invocations * 5, floods.size() * 3);
            }
        }
    }
}

}  // namespace
}  // namespace cutaway::test
