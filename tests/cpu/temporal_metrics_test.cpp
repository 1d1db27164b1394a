// Temporal metrics of animations (issue 44): pops between primary sets, cut flicker between frames.
#include <gtest/gtest.h>

#include <stdexcept>

#include "metrics/image_metrics.h"
#include "metrics/temporal_metrics.h"

namespace cutaway::metrics {
namespace {

TEST(TemporalMetrics, PopsCountCellsEnteringAndLeaving) {
    const PopCounts pops = count_pops({0, 1, 1, 0, 1}, {1, 1, 0, 0, 2});
    EXPECT_EQ(pops.in, 1u);
    EXPECT_EQ(pops.out, 1u);  // 1 -> 2 is primary in both
    EXPECT_THROW(count_pops({0, 1}, {0}), std::invalid_argument);
}

TEST(TemporalMetrics, ReversalsCountOnlyCellsTurningBack) {
    // Cell 0 enters and stays (a front advancing: no reversal); cell 1 hovers at a range limit
    // (in, out, in: two reversals); cell 2 leaves, then comes back (one); cell 3 never changes.
    PopReversals reversals(4);
    EXPECT_EQ(reversals.count({0, 0, 1, 1}, {1, 1, 0, 1}), 0u);  // first changes: nothing to reverse
    EXPECT_EQ(reversals.count({1, 1, 0, 1}, {1, 0, 0, 1}), 1u);  // cell 1 leaves after entering
    EXPECT_EQ(reversals.count({1, 0, 0, 1}, {1, 1, 1, 1}), 2u);  // cell 1 back, cell 2 back
    EXPECT_EQ(reversals.count({1, 1, 1, 1}, {1, 1, 1, 1}), 0u);
    EXPECT_THROW(reversals.count({0, 1}, {0, 1}), std::invalid_argument);
}

TEST(TemporalMetrics, CutAwayIsExactlyTheCutFill) {
    const std::vector<std::uint32_t> cell{0, 5, 5, 7, 7};
    const std::vector<std::uint32_t> flags{flag_cut_fill, 0, flag_cut_fill, flag_primary, flag_cut_fill | flag_border};
    const std::vector<CutState> states = cut_states(cell, flags);
    EXPECT_EQ(states, (std::vector<CutState>{CutState::background, CutState::kept, CutState::cut_away, CutState::kept,
                                              CutState::cut_away}));
}

TEST(TemporalMetrics, FlickerIsTheShareOfModelPixelsThatChanged) {
    using S = CutState;
    // Pixel 0 stays background (not counted); 1 stays kept; 2 kept -> cut; 3 cut -> kept;
    // 4 background -> kept (the model moved under it); 5 stays cut.
    const CutFlicker flicker =
        cut_flicker({S::background, S::kept, S::kept, S::cut_away, S::background, S::cut_away},
                    {S::background, S::kept, S::cut_away, S::kept, S::kept, S::cut_away});
    EXPECT_EQ(flicker.model_pixels, 5u);
    EXPECT_EQ(flicker.changed, 3u);
    EXPECT_DOUBLE_EQ(flicker.fraction, 0.6);
    EXPECT_EQ(cut_flicker({S::background}, {S::background}).fraction, 0.0);
    EXPECT_THROW(cut_flicker({S::kept}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace cutaway::metrics
