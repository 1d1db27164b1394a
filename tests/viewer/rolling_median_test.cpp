// Rolling median: odd and even counts, eviction of the oldest value, ignored non-finite values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "viewer/rolling_median.h"

namespace cutaway::viewer {
namespace {

TEST(RollingMedian, EmptyIsZero) {
    const RollingMedian median(5);
    EXPECT_EQ(median.size(), 0u);
    EXPECT_EQ(median.median(), 0.0);
}

TEST(RollingMedian, OddCountTakesTheMiddleValue) {
    RollingMedian median(5);
    for (double value : {9.0, 1.0, 5.0}) median.add(value);
    EXPECT_EQ(median.size(), 3u);
    EXPECT_EQ(median.median(), 5.0);  // exact: one of the inputs
}

TEST(RollingMedian, EvenCountAveragesTheTwoMiddleValues) {
    RollingMedian median(5);
    for (double value : {4.0, 1.0, 10.0, 2.0}) median.add(value);
    EXPECT_EQ(median.median(), 3.0);  // (2 + 4) / 2 is exact in binary
}

TEST(RollingMedian, FullWindowDropsTheOldestValue) {
    RollingMedian median(3);
    for (double value : {100.0, 200.0, 1.0}) median.add(value);
    EXPECT_EQ(median.median(), 100.0);
    median.add(2.0);  // drops 100: {200, 1, 2}
    EXPECT_EQ(median.size(), 3u);
    EXPECT_EQ(median.median(), 2.0);
    median.add(3.0);  // drops 200: {1, 2, 3}
    EXPECT_EQ(median.median(), 2.0);
    median.add(0.0);  // drops 1: {2, 3, 0}
    EXPECT_EQ(median.median(), 2.0);
    median.add(7.0);  // drops 2: {3, 0, 7}
    EXPECT_EQ(median.median(), 3.0);
}

TEST(RollingMedian, NonFiniteValuesAreIgnored) {
    RollingMedian median(3);
    median.add(1.0);
    median.add(std::nan(""));
    median.add(std::numeric_limits<double>::infinity());
    median.add(3.0);
    EXPECT_EQ(median.size(), 2u);
    EXPECT_EQ(median.median(), 2.0);
}

TEST(RollingMedian, ClearEmpties) {
    RollingMedian median(3);
    median.add(4.0);
    median.clear();
    EXPECT_EQ(median.size(), 0u);
    EXPECT_EQ(median.median(), 0.0);
}

TEST(RollingMedian, WindowZeroIsRefused) { EXPECT_THROW(RollingMedian(0), std::invalid_argument); }

}  // namespace
}  // namespace cutaway::viewer
