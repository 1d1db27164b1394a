#pragma once
// The viewer's playback of a dynamic property over its report steps: the frames of a
// temporal::CoherentSequence (values interpolated and primaries paced under smooth, each step
// held under none, as `cutaway animate` draws them), from a starting step to the last, then
// again from the first. No GL here: the scene uploads what a frame holds.
#include <cstddef>
#include <memory>
#include <optional>

#include "cutaway/temporal/coherent_sequence.h"
#include "cutaway/temporal/step_values.h"

namespace cutaway::viewer {

struct PlaybackSettings {
    temporal::Coherence coherence = temporal::Coherence::smooth;
    std::size_t frames_per_step = 8;  ///< frames from one report step to the next (>= 1)
    grid::PrimaryRange range;         ///< the primary range
    float band = 0;                   ///< hysteresis widening, property units (smooth)
    std::optional<grid::IjkBox> box;
};

class StepPlayer {
public:
    /// Plays `source`'s steps from `start_step` (clamped to the last). `grid` must outlive the player.
    StepPlayer(const grid::CornerPointGrid& grid, std::unique_ptr<temporal::StepValueSource> source,
               PlaybackSettings settings, std::size_t start_step);

    /// The next frame; after the last step's frame, the first step's. Its pointers stay valid
    /// until the next call.
    temporal::CoherentSequence::Frame next();
    const PlaybackSettings& settings() const { return settings_; }
    std::size_t step_count() const { return source_->step_count(); }

private:
    /// A sequence from `first` to the last step.
    void start_at(std::size_t first);

    const grid::CornerPointGrid& grid_;
    std::unique_ptr<temporal::StepValueSource> source_;
    PlaybackSettings settings_;
    temporal::AnimationTimeline timeline_;
    std::unique_ptr<temporal::CoherentSequence> sequence_;
    std::size_t frames_left_ = 0;
};

}  // namespace cutaway::viewer
