// The colour range of a frame whose primaries are picked by the colouring property (issue 46): the
// values' percentiles widened to hold the primaries, so the exposed cells keep their values'
// colours instead of all taking the bar's end colour.
#include <gtest/gtest.h>

#include "app_core/model_source.h"
#include "app_core/render_options.h"

namespace cutaway::app {
namespace {

TEST(ColourRange, WidensToHoldThePrimariesWithinTheValues) {
    // PORO's 2-98th percentiles 0.12-0.30, the top 1% 0.33-0.40, the largest value 0.38.
    const grid::PrimaryRange held = colour_range_holding({0.12f, 0.30f}, {0.33f, 0.40f}, {0.05f, 0.38f}, false);
    EXPECT_FLOAT_EQ(held.min, 0.12f);
    EXPECT_FLOAT_EQ(held.max, 0.38f);  // the largest value, not the range's 0.40 that no cell has
    // A range inside the percentiles changes nothing; one below them widens the low end.
    EXPECT_FLOAT_EQ(colour_range_holding({0.12f, 0.30f}, {0.2f, 0.25f}, {0.05f, 0.38f}, false).max, 0.30f);
    EXPECT_FLOAT_EQ(colour_range_holding({0.12f, 0.30f}, {0.0f, 0.10f}, {0.05f, 0.38f}, false).min, 0.05f);
    // On a log scale the low end stays above 0; a range holding no value leaves the colours alone.
    EXPECT_FLOAT_EQ(colour_range_holding({1.0f, 500.0f}, {0.0f, 0.5f}, {0.0f, 3000.0f}, true).min, 1.0f);
    const grid::PrimaryRange outside = colour_range_holding({0.12f, 0.30f}, {0.5f, 0.6f}, {0.05f, 0.38f}, false);
    EXPECT_FLOAT_EQ(outside.max, 0.30f);
}

TEST(ColourRange, TheTopPercentOfAPresetIsColouredInsideTheBar) {
    // preset:zaphirus coloured and selected by PORO's top 1%: the primary range lies inside the
    // colour range (before the fit, above its 98th percentile).
    LoadedModel model = load_model({"preset:zaphirus"}, std::size_t(1) << 32, "PORO");
    RenderOptions options;
    PropertyChoice property = choose_property(model.grid, options);
    const float percentile_max = property.colour_range.max;
    choose_primary_range(model.grid, property, options);
    EXPECT_GT(property.primary_range.min, percentile_max * 0.999f) << "the top 1% starts above the 98th percentile";
    EXPECT_LE(property.colour_range.min, property.primary_range.min);
    EXPECT_GE(property.colour_range.max, property.primary_range.min);
    EXPECT_GT(property.colour_range.max, percentile_max);
}

}  // namespace
}  // namespace cutaway::app
