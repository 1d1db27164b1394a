#pragma once
// The date an animation frame shows: a fractional report step (an interpolated frame between
// two steps) turned into a calendar date between the two steps' dates. No GL here.
#include <string>
#include <vector>

#include "eclipse/report_steps.h"

namespace cutaway::eclipse {

/// "YYYY-MM-DD" at `time_step` (0-based, fractional) of `steps`: the lower step's date plus the
/// fraction of the days to the next step, rounded to whole days; the last step's date at or beyond
/// it. Empty when `steps` is empty (a model without dates, e.g. a generated flood).
std::string date_at(const std::vector<eclipse::ReportStep>& steps, double time_step);

/// What the viewer and animate write over the frame: "SWAT  2025-11-03  (step 0.5 of 0-30)" for 31
/// report steps (the steps' 0-based indices, as --time-step counts them), without the date when
/// there is none.
std::string step_caption(const std::string& property, const std::string& date, double time_step, std::size_t step_count);

}  // namespace cutaway::eclipse
