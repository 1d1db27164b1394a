// The date of an animation's frame between report steps (step_clock.h).
#include <gtest/gtest.h>

#include "eclipse/step_clock.h"

namespace cutaway::eclipse {
namespace {

eclipse::ReportStep step_on(int year, int month, int day, double elapsed_days) {
    eclipse::ReportStep step;
    step.year = year;
    step.month = month;
    step.day = day;
    step.elapsed_days = elapsed_days;
    return step;
}

TEST(StepClock, DatesBetweenStepsAreInterpolatedInDaysAcrossMonthEnds) {
    // 2025-01-21 + 20 days crosses January's end; 2024 is a leap year (Feb 29 exists).
    const std::vector<eclipse::ReportStep> steps{step_on(2025, 1, 1, 0), step_on(2025, 2, 10, 40), step_on(2025, 3, 12, 70)};
    EXPECT_EQ(date_at(steps, 0), "2025-01-01");
    EXPECT_EQ(date_at(steps, 0.5), "2025-01-21");
    EXPECT_EQ(date_at(steps, 0.75), "2025-01-31");
    EXPECT_EQ(date_at(steps, 1.5), "2025-02-25");  // 15 of the 30 days to March 12
    EXPECT_EQ(date_at(steps, 2), "2025-03-12");
    EXPECT_EQ(date_at(steps, 7), "2025-03-12");  // past the last step: its date
    EXPECT_EQ(date_at({step_on(2024, 2, 28, 0), step_on(2024, 3, 1, 2)}, 0.5), "2024-02-29");
    EXPECT_EQ(date_at({}, 1.5), "");  // a model without dates
}

TEST(StepClock, CaptionNamesPropertyDateAndStep) {
    EXPECT_EQ(step_caption("SWAT", "2025-01-21", 0.5, 31), "SWAT  2025-01-21  (step 0.5 of 0-30)");
    EXPECT_EQ(step_caption("SWAT", "", 3, 6), "SWAT  (step 3 of 0-5)");
}

}  // namespace
}  // namespace cutaway::eclipse
