// The viewer's render size while the view moves (viewer/interaction_resolution.h).
#include <gtest/gtest.h>

#include <initializer_list>
#include <iterator>

#include "viewer/interaction_resolution.h"

namespace cutaway::viewer {
namespace {

/// A frame of `fixed_ms` plus `full_pixel_ms` times the share of the full size's pixels.
double frame_ms(float factor, double fixed_ms, double full_pixel_ms) { return fixed_ms + full_pixel_ms * factor * factor; }

/// `frames` frames of `ms` each at a 10 fps target, then the factor expected.
struct Frames {
    int frames;
    double ms;
    float factor_after;
    const char* why;
};

void expect_factors(std::initializer_list<Frames> sequence) {
    InteractionResolution resolution;
    EXPECT_EQ(resolution.factor(), 0.5f) << "it starts at half the size";
    for (const Frames& f : sequence) {
        for (int i = 0; i < f.frames; ++i) resolution.frame_drawn(f.ms, 10);
        EXPECT_EQ(resolution.factor(), f.factor_after) << f.why;
    }
}

TEST(InteractionResolution, StepsDownWhileFramesAreSlow) {
    expect_factors({{1, 150, 0.5f, "one frame decides nothing"},
                    {1, 150, 0.42f, "two slow frames: one step smaller"},
                    {40, 1000, 0.25f, "never below a quarter of the size"}});
}

TEST(InteractionResolution, OneSlowFrameAmongFastOnesIsNoise) {
    expect_factors({{2, 95, 0.5f, "0.5 -> 0.6 would predict 137 ms: it stays"},
                    {1, 101, 0.5f, "the median of 95, 95 and 101 is within 100 ms"},
                    {1, 96, 0.5f, "the median of 95, 101 and 96 is within 100 ms"}});
}

TEST(InteractionResolution, StepsUpOnlyWhenTheLargerSizeIsPredictedToKeepTheRate) {
    expect_factors({{2, 60, 0.6f, "0.5 -> 0.6 multiplies the pixels by 1.44: 60 ms predicts 86 ms, within 100"},
                    {5, 80, 0.6f, "0.6 -> 0.7 multiplies them by 1.36: 80 ms predicts 109 ms, over the budget"},
                    {40, 1, 1.0f, "fast frames reach the full size and stay there"}});
}

TEST(InteractionResolution, SettlesOnTheLargestSizeThatKeepsTheRateWithoutOscillating) {
    // 40 ms fixed + 400 ms at full size: 10 fps holds up to factor sqrt(60 / 400) = 0.387.
    InteractionResolution resolution;
    for (int i = 0; i < 20; ++i) resolution.frame_drawn(frame_ms(resolution.factor(), 40, 400), 10);
    EXPECT_EQ(resolution.factor(), 0.35f);
    for (int i = 0; i < 20; ++i) {
        resolution.frame_drawn(frame_ms(resolution.factor(), 40, 400), 10);
        EXPECT_EQ(resolution.factor(), 0.35f) << "frame " << i;
    }
    EXPECT_LE(frame_ms(resolution.factor(), 40, 400), 100.0);
}

TEST(InteractionResolution, FactorsFallFromTheFullSizeToAQuarter) {
    const auto& f = InteractionResolution::factors;
    EXPECT_EQ(f[0], 1.0f);
    EXPECT_EQ(f[std::size(f) - 1], 0.25f);
    for (std::size_t i = 1; i < std::size(f); ++i) EXPECT_LT(f[i], f[i - 1]);
}

}  // namespace
}  // namespace cutaway::viewer
