#pragma once
// The primary set of an animation, report step after report step, with hysteresis: a cell enters
// when its value lies in the primary range and stays until its value leaves the range widened by
// a band, so a value hovering at a range limit does not make its cell pop in and out. No OpenGL.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/primary_selection.h"

namespace cutaway::temporal {

class PrimaryTracker {
public:
    /// `band`: property units a primary's value may lie outside `range` and stay primary (>= 0;
    /// 0 selects anew at every frame, the paper's behaviour); `box`: only cells inside it are
    /// primaries (render's --ijk-box). `grid` must outlive the tracker.
    PrimaryTracker(const grid::CornerPointGrid& grid, std::string property, grid::PrimaryRange range, float band,
                   std::optional<grid::IjkBox> box = std::nullopt);

    /// The next step's flags (one per Eclipse cell, 1 = primary; inactive cells never are) from its
    /// `values` (one per cell; NaN in an active cell throws std::invalid_argument naming the
    /// property and the cell).
    const std::vector<std::uint8_t>& update(const std::vector<float>& values);
    const std::vector<std::uint8_t>& flags() const { return flags_; }

private:
    const grid::CornerPointGrid& grid_;
    std::string property_;
    grid::PrimaryRange range_;
    grid::PrimaryRange kept_;  ///< range widened by the band
    std::optional<grid::IjkBox> box_;
    std::vector<std::uint8_t> flags_;
};

}  // namespace cutaway::temporal
