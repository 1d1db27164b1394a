// The cut-error metric on images whose answer is known.
#include <gtest/gtest.h>

#include <vector>

#include "metrics/cut_error.h"

namespace cutaway::metrics {
namespace {

using cone_field::FloatImage;

// An exact cut over 10 x 10 pixels, depths 0 .. 99: the depth range is 99, so the default
// tolerance is 0.099 depth units.
FloatImage ramp() {
    FloatImage image(10, 10);
    for (std::size_t i = 0; i < image.pixel_count(); ++i) image.pixels[i] = float(i);
    return image;
}

TEST(CutError, IdenticalImagesHaveNoError) {
    const CutError error = compare_cut(ramp(), ramp());
    EXPECT_EQ(error.pixels_compared, 100u);
    EXPECT_EQ(error.pixels_wrong, 0u);
    EXPECT_EQ(error.max_abs_error, 0.0);
    EXPECT_EQ(error.max_signed_error, 0.0);
    EXPECT_NEAR(error.tolerance, 0.099, 1e-12);
}

TEST(CutError, CountsPixelsBeyondTheToleranceAndKeepsTheSign) {
    FloatImage cut = ramp();
    cut.pixels[5] -= 2.0f;   // wrong, below exact
    cut.pixels[7] -= 0.05f;  // within 0.099: not wrong
    cut.pixels[9] += 0.5f;   // wrong, above exact
    const CutError error = compare_cut(cut, ramp());
    EXPECT_EQ(error.pixels_wrong, 2u);
    EXPECT_DOUBLE_EQ(error.wrong_fraction, 0.02);
    EXPECT_NEAR(error.max_abs_error, 2.0, 1e-6);
    EXPECT_NEAR(error.max_signed_error, 0.5, 1e-6);
    EXPECT_NEAR(error.min_signed_error, -2.0, 1e-6);
    EXPECT_NEAR(error.mean_abs_error, 2.55 / 100.0, 1e-6);
}

TEST(CutError, MaskSelectsThePixelsCompared) {
    FloatImage cut = ramp();
    cut.pixels[0] = 50.0f;
    std::vector<std::uint8_t> mask(100, 1);
    mask[0] = 0;
    const CutError error = compare_cut(cut, ramp(), {}, mask);
    EXPECT_EQ(error.pixels_compared, 99u);
    EXPECT_EQ(error.pixels_wrong, 0u);
    EXPECT_NEAR(error.tolerance, 0.098, 1e-12);  // range 1 .. 99 over the compared pixels
}

TEST(CutError, FlatExactCutUsesItsDepthAsScale) {
    const CutError error = compare_cut(FloatImage(3, 3, 40.0f), FloatImage(3, 3, 40.0f), {0.01});
    EXPECT_NEAR(error.tolerance, 0.4, 1e-12);
}

}  // namespace
}  // namespace cutaway::metrics
