// The min/max pyramid of the cut depth against a CPU reduction: every texel of every level must
// hold exactly the min and max of the cut texels it covers (min/max of floats is exact, so the
// comparison is exact too).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "cutaway/visibility/cut_depth_pyramid.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

/// Cut texels covered by texel t of `level` along one axis (the last texel takes the leftover).
std::pair<int, int> covered(int t, int level, int level_size, int cut_size) {
    const int first = t << (level + 1);
    const int last = t == level_size - 1 ? cut_size - 1 : ((t + 1) << (level + 1)) - 1;
    return {first, last};
}

void check_pyramid(int width, int height, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> depth(1.0f, 100.0f);
    std::vector<float> cut(std::size_t(width) * std::size_t(height), 0.0f);
    for (float& d : cut) d = random() % 5 == 0 ? 0.0f : depth(random);
    gl::Texture surface(GL_TEXTURE_2D, GL_R32F, width, height);  // as CutTargets::surface
    glTextureSubImage2D(surface.id(), 0, 0, 0, width, height, GL_RED, GL_FLOAT, cut.data());

    pipeline::CutDepthPyramid pyramid(GlEnvironment::shaders());
    pyramid.build(surface);
    ASSERT_EQ(pyramid.level_size(pyramid.levels() - 1), glm::ivec2(1, 1));
    for (int level = 0; level < pyramid.levels(); ++level) {
        const glm::ivec2 size = pyramid.level_size(level);
        const std::vector<glm::vec2> texels = pyramid.read_level(level);
        for (int ty = 0; ty < size.y; ++ty)
            for (int tx = 0; tx < size.x; ++tx) {
                const auto [x0, x1] = covered(tx, level, size.x, width);
                const auto [y0, y1] = covered(ty, level, size.y, height);
                float lo = 1e30f, hi = -1e30f;
                for (int y = y0; y <= y1; ++y)
                    for (int x = x0; x <= x1; ++x) {
                        const float d = cut[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                        lo = std::min(lo, d);
                        hi = std::max(hi, d);
                    }
                const glm::vec2 got = texels[std::size_t(ty) * std::size_t(size.x) + std::size_t(tx)];
                ASSERT_EQ(got.x, lo) << "level " << level << " texel " << tx << "," << ty;
                ASSERT_EQ(got.y, hi) << "level " << level << " texel " << tx << "," << ty;
            }
    }
}

TEST(CutDepthPyramid, EveryLevelHoldsTheMinAndMaxOfTheCutTexelsItCovers) {
    check_pyramid(64, 32, 1);
    check_pyramid(97, 61, 2);    // odd sizes: the last texel takes the leftover
    check_pyramid(1920, 1080, 3);
    check_pyramid(3, 1, 4);
}

}  // namespace
}  // namespace cutaway::test
