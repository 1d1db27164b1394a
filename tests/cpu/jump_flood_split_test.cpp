// The regions of a GPU jump flooding pass (cut_surface/jump_flood_split.h) cover every pixel
// exactly once, with the blocks jump_flood.comp floods: an invocation's first pixel from
// block_start, and along a paired axis that pixel and the one a step further, both inside.
#include <gtest/gtest.h>

#include <vector>

#include "cutaway/cut_surface/jump_flood_split.h"

namespace cutaway::test {
namespace {

/// jump_flood.comp's block_start: along a paired axis invocation i covers i + (i / step) * step.
int block_start(int invocation, bool paired, int step) { return paired ? invocation + invocation / step * step : invocation; }

TEST(JumpFloodSplit, EveryPixelFloodedExactlyOnce) {
    // Sizes: powers of two, odd, smaller than a step, 1080p and 4K (the experiments' sizes).
    const std::vector<std::pair<int, int>> sizes = {{1, 1}, {2, 3}, {7, 5}, {512, 512}, {301, 173}, {640, 360}, {1920, 1080}, {3840, 2160}};
    for (const auto& [width, height] : sizes) {
        for (int step = 1; step <= 4096; step *= 2) {
            SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height) + " step " + std::to_string(step));
            std::vector<int> floods(std::size_t(width) * std::size_t(height), 0);
            std::size_t invocations = 0, pixels_per_invocation = 0;
            for (const pipeline::JumpFloodRegion& region : pipeline::jump_flood_regions(width, height, step)) {
                ASSERT_GT(region.invocations.x, 0);
                ASSERT_GT(region.invocations.y, 0);
                if (region.paired_x) {
                    EXPECT_EQ(region.origin.x, 0);
                }
                if (region.paired_y) {
                    EXPECT_EQ(region.origin.y, 0);
                }
                const int block_x = region.paired_x ? 2 : 1, block_y = region.paired_y ? 2 : 1;
                invocations += std::size_t(region.invocations.x) * std::size_t(region.invocations.y);
                pixels_per_invocation += std::size_t(region.invocations.x) * std::size_t(region.invocations.y) * std::size_t(block_x * block_y);
                for (int iy = 0; iy < region.invocations.y; ++iy)
                    for (int ix = 0; ix < region.invocations.x; ++ix)
                        for (int by = 0; by < block_y; ++by)
                            for (int bx = 0; bx < block_x; ++bx) {
                                const int x = region.origin.x + block_start(ix, region.paired_x, step) + bx * step;
                                const int y = region.origin.y + block_start(iy, region.paired_y, step) + by * step;
                                ASSERT_TRUE(x >= 0 && x < width && y >= 0 && y < height) << "pixel " << x << ", " << y << " outside";
                                ++floods[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                            }
            }
            for (std::size_t i = 0; i < floods.size(); ++i) ASSERT_EQ(floods[i], 1) << "pixel " << i % std::size_t(width) << ", " << i / std::size_t(width);
            EXPECT_EQ(pixels_per_invocation, floods.size());
            if (width >= 4 * step && height >= 4 * step) {  // mostly whole spans: most blocks are 2 x 2
                EXPECT_LT(invocations, floods.size() * 2 / 5);
            }
        }
    }
}

}  // namespace
}  // namespace cutaway::test
