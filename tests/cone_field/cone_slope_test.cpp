// The perspective-corrected cone slope m = s / (tan(theta) f).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cone_field/cone_slope.h"

namespace cutaway::cone_field {
namespace {

TEST(ConeSlope, FortyFiveDegreesIsOnePixelFootprintPerPixel) {
    // At 45 degrees the wall moves one eye unit sideways per unit of depth, and one pixel at depth
    // 100 with a 500-pixel focal length spans 0.2 eye units.
    EXPECT_NEAR(cone_slope_per_pixel(std::numbers::pi / 4, 100.0, 500.0), 0.2, 1e-12);
}

TEST(ConeSlope, WiderApertureAndNearerDepthGiveAFlatterCone) {
    const double narrow = cone_slope_per_pixel(0.2, 100.0, 800.0);
    EXPECT_GT(narrow, cone_slope_per_pixel(1.2, 100.0, 800.0));
    EXPECT_GT(narrow, cone_slope_per_pixel(0.2, 50.0, 800.0));
    EXPECT_NEAR(narrow, 100.0 / (std::tan(0.2) * 800.0), 1e-12);
}

TEST(ConeHeight, FallsWithEuclideanDistance) {
    EXPECT_DOUBLE_EQ(cone_height(10.0, 2.0, 3, -4), 0.0);
    EXPECT_DOUBLE_EQ(cone_height(10.0, 2.0, 0, 0), 10.0);
}

}  // namespace
}  // namespace cutaway::cone_field
