#pragma once
// Where `animate` reads a dynamic property's report steps: a simulator case's UNRST, one step per
// read (eclipse::ReportSteps), or the steps a grid holds (a generated flood).
#include <memory>
#include <string>

#include "app_core/model_source.h"
#include "cutaway/temporal/step_values.h"

namespace cutaway::app {

/// The steps of `property` in `model`. Throws std::invalid_argument naming --property when the
/// model has no time steps of it.
std::unique_ptr<temporal::StepValueSource> step_values_of(const LoadedModel& model, const std::string& property);

}  // namespace cutaway::app
