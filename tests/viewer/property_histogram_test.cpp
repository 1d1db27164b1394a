// Histogram of a property over active cells: bin placement, skipped cells, refused inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "grid/box_grid.h"
#include "viewer/property_histogram.h"

namespace cutaway::viewer {
namespace {

/// A 3x2x2 box (12 cells) with cells 1 and 7 inactive.
grid::CornerPointGrid box_with_two_inactive_cells() {
    grid::BoxGridSpec spec;
    spec.dims = {3, 2, 2};
    const grid::CornerPointGrid box = grid::make_box_grid(spec);
    std::vector<std::uint8_t> actnum(box.cell_count(), 1);
    actnum[1] = actnum[7] = 0;
    return grid::CornerPointGrid(box.dims(), box.coord(), box.zcorn(), actnum);
}

/// 0, 1, 2, ... 11: cell index as value.
std::vector<float> cell_indices(const grid::CornerPointGrid& grid) {
    std::vector<float> values(grid.cell_count());
    std::iota(values.begin(), values.end(), 0.0f);
    return values;
}

float sum(const std::vector<float>& counts) { return std::accumulate(counts.begin(), counts.end(), 0.0f); }

TEST(PropertyHistogram, CountsActiveFiniteCellsAndPutsMaxInTheLastBin) {
    const grid::CornerPointGrid grid = box_with_two_inactive_cells();
    ASSERT_EQ(grid.active_count(), 10u);
    std::vector<float> values = cell_indices(grid);
    values[1] = 1000;           // inactive: must not widen the range
    values[4] = std::nanf("");  // active but not finite: skipped
    const PropertyHistogram histogram = active_histogram(grid, values, 4);
    EXPECT_EQ(histogram.min, 0.0f);
    EXPECT_EQ(histogram.max, 11.0f);
    EXPECT_EQ(histogram.cells, 9u);
    ASSERT_EQ(histogram.counts.size(), 4u);
    EXPECT_EQ(sum(histogram.counts), 9.0f);
    // Bin width 11/4 = 2.75: {0, 2}, {3, 5}, {6, 8}, {9, 10, 11} (1, 4 and 7 skipped).
    EXPECT_EQ(histogram.counts[0], 2.0f);
    EXPECT_EQ(histogram.counts[1], 2.0f);
    EXPECT_EQ(histogram.counts[2], 2.0f);
    EXPECT_EQ(histogram.counts[3], 3.0f);
}

TEST(PropertyHistogram, ConstantPropertyFillsBinZero) {
    const grid::CornerPointGrid grid = box_with_two_inactive_cells();
    const PropertyHistogram histogram = active_histogram(grid, std::vector<float>(grid.cell_count(), 0.25f), 8);
    EXPECT_EQ(histogram.min, 0.25f);
    EXPECT_EQ(histogram.max, 0.25f);
    EXPECT_EQ(histogram.counts[0], 10.0f);
    EXPECT_EQ(sum(histogram.counts), 10.0f);
}

TEST(PropertyHistogram, NoFiniteValueGivesEmptyBins) {
    const grid::CornerPointGrid grid = box_with_two_inactive_cells();
    const PropertyHistogram histogram = active_histogram(grid, std::vector<float>(grid.cell_count(), NAN), 3);
    EXPECT_EQ(histogram.cells, 0u);
    EXPECT_EQ(histogram.counts, std::vector<float>(3, 0.0f));
}

TEST(PropertyHistogram, SizeMismatchNamesBothSizes) {
    const grid::CornerPointGrid grid = box_with_two_inactive_cells();
    try {
        active_histogram(grid, std::vector<float>(11, 0.0f), 4);
        FAIL() << "size mismatch accepted";
    } catch (const std::invalid_argument& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("11"), std::string::npos) << message;
        EXPECT_NE(message.find("12"), std::string::npos) << message;
    }
}

TEST(PropertyHistogram, ZeroBinsAreRefused) {
    const grid::CornerPointGrid grid = box_with_two_inactive_cells();
    EXPECT_THROW(active_histogram(grid, cell_indices(grid), 0), std::invalid_argument);
}

}  // namespace
}  // namespace cutaway::viewer
