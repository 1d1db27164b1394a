#include "viewer/interaction_resolution.h"

#include <iterator>

namespace cutaway::viewer {

void InteractionResolution::frame_drawn(double frame_ms, double target_fps) {
    recent_ms_.add(frame_ms);
    if (recent_ms_.size() < frames_to_decide) return;
    const double median = recent_ms_.median();
    const double budget_ms = 1000.0 / target_fps;
    if (median > budget_ms) {
        if (level_ + 1 < std::size(factors)) step_to(level_ + 1);
        return;
    }
    if (level_ == 0) return;
    const double ratio = double(factors[level_ - 1]) / double(factors[level_]);
    if (median * ratio * ratio <= budget_ms) step_to(level_ - 1);
}

void InteractionResolution::step_to(std::size_t level) {
    level_ = level;
    recent_ms_.clear();
}

}  // namespace cutaway::viewer
