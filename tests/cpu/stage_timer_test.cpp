// query_agrees: when a GL timer query is believed next to the fenced wall time of its stage.
#include <gtest/gtest.h>

#include "gl/stage_timer.h"

namespace {

using cutaway::gl::query_agrees;

TEST(StageTimerQuery, AgreesWhenItIsCloseToTheWallTime) {
    EXPECT_TRUE(query_agrees(100.0, 95.0));   // a real GPU: the wall clock adds submission
    EXPECT_TRUE(query_agrees(100.0, 104.0));  // the two clocks' granularity
    EXPECT_TRUE(query_agrees(0.2, 0.6));      // sub-millisecond stages: within 0.5 ms
}

TEST(StageTimerQuery, RejectsAQueryFarShorterThanTheWallTime) {
    EXPECT_FALSE(query_agrees(100.0, 3.0));  // llvmpipe timing its last tile only (SPEC.md section 5)
}

TEST(StageTimerQuery, RejectsAQueryLongerThanTheFencesAroundIt) {
    EXPECT_FALSE(query_agrees(1615.7, 71856973.2));  // what llvmpipe returned for scale-10m's cut stage
    EXPECT_FALSE(query_agrees(100.0, 150.0));
}

}  // namespace
