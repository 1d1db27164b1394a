// The GPU jump flooding pass decides each tap by "higher" alone (shaders/cut_surface/
// jump_flood_rule.glsl): a texel with no owner (0, also what a tap outside the image reads)
// decodes as a seed at (65535, 65535) of stored depth 0, and its cone must lie strictly below
// every real owner's cone at every pixel of the largest image the cone fields accept, for every
// slope the renderer can give (> 0). Computed here in float as the shader does, with and without
// the multiply-add fused (a GLSL compiler may contract it), so raising max_image_side past what
// the 16-bit owner coordinates allow makes this fail.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cone_field/cone_image.h"

namespace cutaway::test {
namespace {

constexpr float no_owner_at = 65535.0f;  // (q - 1) of texel 0: both 16-bit halves all ones

float distance(float qx, float qy, float px, float py) {
    const float dx = qx - px, dy = qy - py;
    return std::sqrt(dx * dx + dy * dy);
}

float height(float depth, float slope, float dist, bool fused) { return fused ? std::fma(-slope, dist, depth) : depth - slope * dist; }

TEST(JumpFloodNoOwner, LiesBelowEveryOwnerInTheLargestImage) {
    const float last = float(cone_field::max_image_side - 1);
    ASSERT_LT(cone_field::max_image_side, 65536) << "owner coordinates are packed in 16 bits";
    const std::vector<float> pixels = {0.0f, last / 2.0f, last};
    // From an almost flat cone (aperture near 180 degrees) to a needle; stored depths in (0, 1].
    const std::vector<float> slopes = {1e-20f, 1e-9f, 1e-6f, 1e-3f, 0.01f, 1.0f, 1e3f, 1e6f, 1e20f};
    const std::vector<float> depths = {1e-30f, 1e-7f, 0.5f, 1.0f};
    for (const bool fused : {false, true})
        for (const float slope : slopes)
            for (const float px : pixels)
                for (const float py : pixels) {
                    const float none = height(0.0f, slope, distance(no_owner_at, no_owner_at, px, py), fused);
                    // The real owners farthest from the pixel: the image's corners.
                    for (const float qx : {0.0f, last})
                        for (const float qy : {0.0f, last})
                            for (const float depth : depths) {
                                const float owner = height(depth, slope, distance(qx, qy, px, py), fused);
                                EXPECT_GT(owner, none) << "slope " << slope << " pixel " << px << "," << py << " owner " << qx << ","
                                                       << qy << " depth " << depth << (fused ? " fused" : "");
                            }
                }
}

}  // namespace
}  // namespace cutaway::test
