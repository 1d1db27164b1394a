#pragma once
// Where an animation reads a dynamic property: "values of property P at report step K". The one
// seam between the animation and the model's storage (a generated flood held in memory today, a
// restart file read step by step on demand tomorrow). No OpenGL here.
#include <cstddef>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/primary_selection.h"

namespace cutaway::temporal {

class StepValueSource {
public:
    virtual ~StepValueSource() = default;
    /// The property's name (its keyword, e.g. SWAT).
    virtual const std::string& property() const = 0;
    /// Report steps the property has (0-based steps 0 .. step_count() - 1).
    virtual std::size_t step_count() const = 0;
    /// One value per Eclipse cell (NX*NY*NZ, inactive cells included) at report `step`
    /// (< step_count()); a reader may load the step on this call, so callers keep what they need.
    virtual std::vector<float> values(std::size_t step) const = 0;
};

/// The smallest and largest value over active cells of steps first..last (inclusive) of `source`:
/// one colour scale for an animation over them. Reads each step once.
grid::PrimaryRange value_range_over_steps(const grid::CornerPointGrid& grid, const StepValueSource& source,
                                          std::size_t first, std::size_t last);

/// Steps held in a CornerPointGrid (CornerPointGrid::dynamic_property).
class GridStepValues final : public StepValueSource {
public:
    /// Throws std::invalid_argument naming --property when `grid` has no time steps of `property`
    /// (a static property, or none of that name).
    GridStepValues(const grid::CornerPointGrid& grid, std::string property);
    const std::string& property() const override { return property_; }
    std::size_t step_count() const override { return grid_.step_count(property_); }
    std::vector<float> values(std::size_t step) const override;

private:
    const grid::CornerPointGrid& grid_;
    std::string property_;
};

}  // namespace cutaway::temporal
