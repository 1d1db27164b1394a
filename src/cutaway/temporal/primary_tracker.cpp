#include "cutaway/temporal/primary_tracker.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace cutaway::temporal {

PrimaryTracker::PrimaryTracker(const grid::CornerPointGrid& grid, std::string property, grid::PrimaryRange range, float band,
                               std::optional<grid::IjkBox> box)
    : grid_(grid), property_(std::move(property)), range_(range), kept_{range.min - band, range.max + band}, box_(box) {
    if (!(band >= 0.0f) || !std::isfinite(band))
        throw std::invalid_argument("hysteresis band: expected a finite value >= 0, found " + std::to_string(band));
}

const std::vector<std::uint8_t>& PrimaryTracker::update(const std::vector<float>& values) {
    // select_primaries checks the values (size, NaN in active cells) and gives the cells that enter.
    std::vector<std::uint8_t> next = grid::select_primaries(grid_, values, property_, range_, box_);
    if (flags_.size() == next.size())
        for (std::size_t c = 0; c < next.size(); ++c)
            if (flags_[c] && !next[c] && values[c] >= kept_.min && values[c] <= kept_.max) next[c] = 1;
    flags_ = std::move(next);
    return flags_;
}

}  // namespace cutaway::temporal
