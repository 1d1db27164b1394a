#include "app_core/step_value_sources.h"

#include "eclipse/report_steps.h"

namespace cutaway::app {
namespace {

/// A restart array read from the UNRST at each values() call: one step in memory at a time.
class RestartStepValues final : public temporal::StepValueSource {
public:
    RestartStepValues(std::shared_ptr<const eclipse::ReportSteps> steps, std::string property)
        : steps_(std::move(steps)), property_(std::move(property)) {}
    const std::string& property() const override { return property_; }
    std::size_t step_count() const override { return steps_->step_count(); }
    std::vector<float> values(std::size_t step) const override { return steps_->values(property_, step); }

private:
    std::shared_ptr<const eclipse::ReportSteps> steps_;
    std::string property_;
};

}  // namespace

std::unique_ptr<temporal::StepValueSource> step_values_of(const LoadedModel& model, const std::string& property) {
    if (model.report_steps && model.report_steps->has_property(property))
        return std::make_unique<RestartStepValues>(model.report_steps, property);
    return std::make_unique<temporal::GridStepValues>(model.grid, property);
}

}  // namespace cutaway::app
