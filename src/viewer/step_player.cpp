#include "viewer/step_player.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace cutaway::viewer {

StepPlayer::StepPlayer(const grid::CornerPointGrid& grid, std::unique_ptr<temporal::StepValueSource> source,
                       PlaybackSettings settings, std::size_t start_step)
    : grid_(grid), source_(std::move(source)), settings_(std::move(settings)) {
    if (source_->step_count() == 0) throw std::invalid_argument("play: property " + source_->property() + " has no time steps");
    settings_.frames_per_step = std::max<std::size_t>(settings_.frames_per_step, 1);
    start_at(std::min(start_step, source_->step_count() - 1));
}

void StepPlayer::start_at(std::size_t first) {
    timeline_ = {first, source_->step_count() - 1, settings_.frames_per_step};
    sequence_ = std::make_unique<temporal::CoherentSequence>(grid_, *source_, timeline_, settings_.coherence, settings_.range,
                                                             settings_.band, settings_.box);
    frames_left_ = timeline_.frame_count();
}

temporal::CoherentSequence::Frame StepPlayer::next() {
    if (frames_left_ == 0) start_at(0);  // from the last step back to the first
    --frames_left_;
    return sequence_->next();
}

}  // namespace cutaway::viewer
