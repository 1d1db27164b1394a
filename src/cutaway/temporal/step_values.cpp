#include "cutaway/temporal/step_values.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace cutaway::temporal {
namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text.append(text.empty() ? "" : ", ").append(name);
    return text.empty() ? "none" : text;
}

}  // namespace

grid::PrimaryRange value_range_over_steps(const grid::CornerPointGrid& grid, const StepValueSource& source,
                                          std::size_t first, std::size_t last) {
    grid::PrimaryRange range;
    for (std::size_t step = first; step <= last; ++step) {
        const grid::PrimaryRange r = grid::active_value_range(grid, source.values(step), source.property());
        range = step == first ? r : grid::PrimaryRange{std::min(range.min, r.min), std::max(range.max, r.max)};
    }
    return range;
}

GridStepValues::GridStepValues(const grid::CornerPointGrid& grid, std::string property)
    : grid_(grid), property_(std::move(property)) {
    if (grid_.step_count(property_) > 0) return;
    if (grid_.property(property_) || grid_.int_property(property_))
        throw std::invalid_argument("--property " + property_ + ": expected a property with time steps, found a static one");
    throw std::invalid_argument("--property " + property_ + ": expected a property with time steps (the model's: " +
                                joined(grid_.dynamic_property_names()) + ")");
}

std::vector<float> GridStepValues::values(std::size_t step) const {
    if (step >= step_count())
        throw std::invalid_argument("step " + std::to_string(step) + " of " + property_ + ": expected 0.." +
                                    std::to_string(step_count() - 1));
    return *grid_.dynamic_property(property_, step);
}

}  // namespace cutaway::temporal
