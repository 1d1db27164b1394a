// What `inspect` reports of a property: nearest-rank percentiles over the active cells only.
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "app_core/property_statistics.h"
#include "grid/box_grid.h"

namespace cutaway::app {
namespace {

TEST(PropertyStatistics, NearestRankPercentilesOfActiveCells) {
    grid::BoxGridSpec spec;
    spec.dims = {10, 10, 2};
    grid::CornerPointGrid box = grid::make_box_grid(spec);
    // Layer 0 holds 1..100; layer 1 holds a large value: inactive cells must not count.
    std::vector<std::uint8_t> actnum(200, 0);
    std::vector<float> values(200, 1e6f);
    for (int cell = 0; cell < 100; ++cell) {
        actnum[cell] = 1;
        values[cell] = float(100 - cell);  // reversed: the order of the cells must not matter
    }
    const grid::CornerPointGrid grid(spec.dims, box.coord(), box.zcorn(), actnum);
    const nlohmann::json s = property_statistics(grid, values, "X");
    // The value at position round(f * (n - 1)) of the sorted 1..100 (what render's colour range uses),
    // i.e. round(f * 99) + 1.
    EXPECT_EQ(s["min"].get<double>(), 1);
    EXPECT_EQ(s["p2"].get<double>(), 3);
    EXPECT_EQ(s["p25"].get<double>(), 26);
    EXPECT_EQ(s["p50"].get<double>(), 51);
    EXPECT_EQ(s["p75"].get<double>(), 75);
    EXPECT_EQ(s["p98"].get<double>(), 98);
    EXPECT_EQ(s["max"].get<double>(), 100);
    EXPECT_EQ(s["positive"].get<double>(), 1.0);
    EXPECT_NE(property_statistics_text({{"X", s}}).find("p98 98"), std::string::npos);
}

TEST(PropertyStatistics, NonFiniteActiveValueIsNamed) {
    grid::BoxGridSpec spec;
    const grid::CornerPointGrid grid = grid::make_box_grid(spec);
    std::vector<float> values(grid.dims().cell_count(), 1.0f);
    values[3] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(
        {
            try {
                property_statistics(grid, values, "PORO");
            } catch (const std::invalid_argument& e) {
                EXPECT_NE(std::string(e.what()).find("PORO"), std::string::npos);
                throw;
            }
        },
        std::invalid_argument);
}

}  // namespace
}  // namespace cutaway::app
