// Primary selection: range, IJK box, top fraction, bad values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>

#include "grid/box_grid.h"
#include "grid/primary_selection.h"

namespace cutaway::grid {
namespace {

CornerPointGrid box_4x4x4() {
    BoxGridSpec spec;
    spec.dims = {4, 4, 4};
    return make_box_grid(spec);
}

std::vector<float> ramp(std::size_t n) {
    std::vector<float> v(n);
    std::iota(v.begin(), v.end(), 0.0f);
    return v;
}

TEST(PrimarySelection, RangeIsInclusiveAndBoxRestricts) {
    const CornerPointGrid grid = box_4x4x4();
    const std::vector<float> values = ramp(64);
    EXPECT_EQ(count_primaries(select_primaries(grid, values, "V", {10, 19})), 10u);
    const IjkBox box{0, 0, 0, 3, 3, 0};  // layer 0 holds values 0..15
    EXPECT_EQ(count_primaries(select_primaries(grid, values, "V", {10, 19}, box)), 6u);
}

TEST(PrimarySelection, FractionTakesTheTopValues) {
    const CornerPointGrid grid = box_4x4x4();
    const std::vector<float> values = ramp(64);
    const PrimaryRange range = range_for_fraction(grid, values, "V", 0.25);
    EXPECT_FLOAT_EQ(range.min, 48);
    EXPECT_FLOAT_EQ(range.max, 63);
    EXPECT_EQ(count_primaries(select_primaries(grid, values, "V", range)), 16u);
    EXPECT_EQ(count_primaries(select_primaries(grid, values, "V", range_for_fraction(grid, values, "V", 1e-6))), 1u);
}

TEST(PrimarySelection, QuantileRangeIgnoresOutliersAndKeepsPositiveValuesForLogScales) {
    // The colour range: 2nd to 98th percentile by nearest rank over the 64 active values, so the
    // one outlier at the top (1e6 among 0..62) does not set the range's end; on a log scale only
    // values above 0 count (the ramp's 0 and the negative ones are left out).
    const CornerPointGrid grid = box_4x4x4();
    std::vector<float> values = ramp(64);
    values[63] = 1e6f;
    const PrimaryRange linear = active_quantile_range(grid, values, "V", 0.02, 0.98, false);
    EXPECT_FLOAT_EQ(linear.min, 1);   // rank round(0.02 * 63) = 1
    EXPECT_FLOAT_EQ(linear.max, 62);  // rank round(0.98 * 63) = 62: below the outlier
    for (std::size_t c = 0; c < 8; ++c) values[c] = -float(c);
    const PrimaryRange positive = active_quantile_range(grid, values, "V", 0, 1, true);
    EXPECT_FLOAT_EQ(positive.min, 8);
    EXPECT_FLOAT_EQ(positive.max, 1e6f);
    const std::vector<float> none(64, 0.0f);
    const PrimaryRange empty = active_quantile_range(grid, none, "V", 0.02, 0.98, true);
    EXPECT_EQ(empty.min, 0);
    EXPECT_EQ(empty.max, 0);
}

TEST(PrimarySelection, NaNInAnActiveCellNamesPropertyAndCell) {
    const CornerPointGrid grid = box_4x4x4();
    std::vector<float> values = ramp(64);
    values[grid.dims().cell_index(1, 2, 3)] = std::nanf("");
    try {
        select_primaries(grid, values, "PORO", {0, 100});
        FAIL() << "NaN accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "property PORO: NaN in active cell (i,j,k) = (1,2,3), expected a finite number");
    }
    EXPECT_THROW(range_for_fraction(grid, values, "PORO", 0.1), std::invalid_argument);
    values[grid.dims().cell_index(1, 2, 3)] = -std::numeric_limits<float>::infinity();
    try {
        check_finite_active(grid, values, "PORO");
        FAIL() << "-inf accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "property PORO: -inf in active cell (i,j,k) = (1,2,3), expected a finite number");
    }
}

TEST(PrimarySelection, BadFractionAndSizeAreRefused) {
    const CornerPointGrid grid = box_4x4x4();
    EXPECT_THROW(range_for_fraction(grid, ramp(64), "V", 0.0), std::invalid_argument);
    EXPECT_THROW(range_for_fraction(grid, ramp(64), "V", 1.5), std::invalid_argument);
    EXPECT_THROW(select_primaries(grid, ramp(63), "V", {0, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace cutaway::grid
