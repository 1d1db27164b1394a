// Input that cannot give a cut is refused with std::invalid_argument and a message naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "cone_field/brute_force.h"
#include "cone_field/chamfer.h"
#include "cone_field/cone_slope.h"
#include "cone_field/exact_reference.h"
#include "cone_field/jump_flooding.h"
#include "metrics/cut_error.h"

namespace cutaway::cone_field {
namespace {

struct BadCase {
    const char* name;
    std::function<void()> call;
    const char* message;  ///< part of the error text
};

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, RefusedWithClearMessage) {
    try {
        GetParam().call();
        FAIL() << "accepted " << GetParam().name;
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find(GetParam().message), std::string::npos) << error.what();
    }
}

SeedImage small_seeds() {
    SeedImage seeds(8, 8);
    seeds.set_seed(3, 3, 10.0f);
    return seeds;
}

SeedImage seeds_with(float depth) {
    SeedImage seeds = small_seeds();
    seeds.set_seed(1, 1, depth);
    return seeds;
}

SeedImage inconsistent_seeds() {
    SeedImage seeds = small_seeds();
    seeds.depth.width = 9;
    return seeds;
}

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

INSTANTIATE_TEST_SUITE_P(
    ConeField, BadInput,
    ::testing::Values(
        BadCase{"zero_width", [] { SeedImage(0, 5); }, "size must be positive"},
        BadCase{"negative_height", [] { FloatImage(5, -1); }, "size must be positive"},
        BadCase{"absurd_size", [] { SeedImage(100000, 100000); }, "beyond the limit"},
        BadCase{"too_many_pixels", [] { SeedImage(30000, 30000); }, "beyond the limit"},
        BadCase{"inconsistent_image", [] { brute_force_cut(inconsistent_seeds(), 1.0); }, "its size says"},
        BadCase{"default_image", [] { exact_reference_cut(SeedImage(), 1.0); }, "size must be positive"},
        BadCase{"nan_seed", [] { chamfer_cut(seeds_with(float(nan)), 1.0, ChamferMask::borgefors_3x3); }, "finite"},
        BadCase{"infinite_seed",
                [] { jump_flooding_cut(seeds_with(std::numeric_limits<float>::infinity()), 1.0, JfaVariant::jfa); },
                "finite"},
        BadCase{"zero_slope_brute", [] { brute_force_cut(small_seeds(), 0.0); }, "slope m must be positive"},
        BadCase{"negative_slope_exact", [] { exact_reference_cut(small_seeds(), -1.0); }, "slope m must be positive"},
        BadCase{"nan_slope_chamfer", [] { chamfer_cut(small_seeds(), nan, ChamferMask::borgefors_5x5); },
                "slope m must be positive"},
        BadCase{"infinite_slope_jfa",
                [] { jump_flooding_cut(small_seeds(), std::numeric_limits<double>::infinity(), JfaVariant::jfa); },
                "slope m must be positive"},
        BadCase{"zero_jfa_step", [] { jump_flooding_cut(small_seeds(), 1.0, std::vector<int>{4, 0}); },
                "steps must be"},
        BadCase{"jfa_steps_empty_image", [] { jfa_steps(JfaVariant::jfa, 0, 10); }, "size must be positive"},
        BadCase{"absurd_thread_count", [] { exact_reference_cut(small_seeds(), 1.0, {5000, 16}); }, "thread count"},
        BadCase{"zero_tile", [] { exact_reference_cut(small_seeds(), 1.0, {1, 0}); }, "tile size"},
        BadCase{"zero_aperture", [] { cone_slope_per_pixel(0.0, 10.0, 500.0); }, "theta"},
        BadCase{"right_angle_aperture", [] { cone_slope_per_pixel(std::numbers::pi / 2, 10.0, 500.0); }, "theta"},
        BadCase{"nan_aperture", [] { cone_slope_per_pixel(nan, 10.0, 500.0); }, "theta"},
        BadCase{"zero_reference_depth", [] { cone_slope_per_pixel(0.5, 0.0, 500.0); }, "reference depth"},
        BadCase{"negative_focal", [] { cone_slope_per_pixel(0.5, 10.0, -1.0); }, "focal length"},
        BadCase{"mismatched_cut_sizes", [] { metrics::compare_cut(FloatImage(4, 4), FloatImage(4, 5)); },
                "but the exact cut is"},
        BadCase{"mask_size",
                [] { metrics::compare_cut(FloatImage(4, 4), FloatImage(4, 4), {}, std::vector<std::uint8_t>(3)); },
                "mask holds"},
        BadCase{"negative_tolerance", [] { metrics::compare_cut(FloatImage(4, 4), FloatImage(4, 4), {-1.0}); },
                "relative tolerance"},
        BadCase{"nan_pixel", [] { metrics::compare_cut(FloatImage(4, 4, float(nan)), FloatImage(4, 4)); }, "NaN"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace cutaway::cone_field
