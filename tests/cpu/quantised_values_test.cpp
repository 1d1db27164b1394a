// 16-bit colouring values (src/cutaway/quantised_values.h): every finite value decodes within
// half a code of itself, the extremes are exact, constant and non-finite values are handled.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "cutaway/quantised_values.h"

namespace cutaway::pipeline {
namespace {

float decoded(const QuantisedValues& q, std::size_t c) { return q.offset + q.span * float(q.codes[c]) / 65535.0f; }

TEST(QuantiseUnorm16, DecodesEachValueWithinHalfACode) {
    std::mt19937 random(3);
    std::uniform_real_distribution<float> pressure(180.0f, 420.0f);
    std::vector<float> values(5000);
    for (float& v : values) v = pressure(random);
    const QuantisedValues q = quantise_unorm16(values);
    ASSERT_EQ(q.codes.size(), values.size());
    // Half a code of the span, plus float rounding of offset + span x t (a few ulps of 420).
    const float tolerance = q.span / 131070.0f + 4 * std::numeric_limits<float>::epsilon() * 420.0f;
    for (std::size_t c = 0; c < values.size(); ++c) EXPECT_NEAR(decoded(q, c), values[c], tolerance) << c;
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    EXPECT_EQ(q.codes[std::size_t(low - values.begin())], 0);
    EXPECT_EQ(q.codes[std::size_t(high - values.begin())], 65535);
    EXPECT_EQ(q.offset, *low);
}

TEST(QuantiseUnorm16, ConstantValuesDecodeToThemselves) {
    const QuantisedValues q = quantise_unorm16(std::vector<float>(10, 0.25f));
    EXPECT_EQ(q.span, 0.0f);
    for (std::size_t c = 0; c < 10; ++c) EXPECT_EQ(decoded(q, c), 0.25f);
}

TEST(QuantiseUnorm16, NonFiniteValuesTakeTheLowestCodeAndNoPartInTheSpan) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const QuantisedValues q = quantise_unorm16(std::vector<float>{0.5f, nan, 1.5f, -inf});
    EXPECT_EQ(q.offset, 0.5f);
    EXPECT_EQ(q.span, 1.0f);
    EXPECT_EQ(q.codes, (std::vector<std::uint16_t>{0, 0, 65535, 0}));
    EXPECT_EQ(quantise_unorm16(std::vector<float>{nan}).codes, std::vector<std::uint16_t>{0});
}

}  // namespace
}  // namespace cutaway::pipeline
