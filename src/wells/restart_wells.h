#pragma once
// Wells of a simulator case at one report step, from its UNRST (ZWEL, IWEL, ICON through EclIO).
#include <cstddef>
#include <vector>

#include "eclipse/report_steps.h"
#include "wells/well.h"

namespace cutaway::wells {

/// The restart's description of a step's wells as Wells (type and status by name).
std::vector<Well> wells_from_restart(const std::vector<eclipse::WellAtStep>& step_wells);

/// The wells at report step `index` (0-based) of `steps`. Throws eclipse::EclipseError.
std::vector<Well> restart_wells(const eclipse::ReportSteps& steps, std::size_t index);

}  // namespace cutaway::wells
