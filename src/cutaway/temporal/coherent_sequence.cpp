#include "cutaway/temporal/coherent_sequence.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace cutaway::temporal {

CoherentSequence::CoherentSequence(const grid::CornerPointGrid& grid, const StepValueSource& source,
                                   const AnimationTimeline& timeline, Coherence coherence,
                                   const grid::PrimaryRange& range, float band, const std::optional<grid::IjkBox>& box)
    : source_(source), timeline_(timeline), coherence_(coherence), range_(range),
      band_(coherence == Coherence::smooth ? band : 0.0f), tracker_(grid, source.property(), range, band_, box) {
    if (timeline_.frames_per_step == 0 || timeline_.first_step > timeline_.last_step || timeline_.last_step >= source_.step_count())
        throw std::invalid_argument("animation steps " + std::to_string(timeline_.first_step) + ".." +
                                    std::to_string(timeline_.last_step) + ": expected FIRST <= LAST < " +
                                    std::to_string(source_.step_count()) + " and frames per step >= 1");
    if (coherence_ == Coherence::smooth) openings_.emplace(frames_to_open(timeline_.frames_per_step), grid.dims());
}

CoherentSequence::Frame CoherentSequence::counted(Frame frame) {
    frame.primary_cells = std::size_t(std::count_if(frame.flags->begin(), frame.flags->end(), [](std::uint8_t f) { return f != 0; }));
    return frame;
}

std::vector<float> CoherentSequence::read(std::size_t step) {
    ++steps_read_;
    return source_.values(step);
}

void CoherentSequence::advance_to(std::size_t step) {
    if (upper_step_ == step) {
        // Frames moved on by one step: the upper step and its flags become the lower ones.
        std::swap(lower_, upper_);
        std::swap(was_, is_);
    } else {
        lower_ = read(step);
        was_ = tracker_.update(lower_);
    }
    lower_step_ = step;
    upper_step_.reset();
    if (coherence_ == Coherence::smooth && step < timeline_.last_step) {
        upper_ = read(step + 1);
        is_ = tracker_.update(upper_);
        upper_step_ = step + 1;
        transition_ = PacedTransition(lower_, upper_, was_, is_, range_, band_);
    }
}

CoherentSequence::Frame CoherentSequence::next() {
    if (returned_frames_ >= timeline_.frame_count())
        throw std::logic_error("animation: frame " + std::to_string(returned_frames_) + " past the last (" +
                               std::to_string(timeline_.frame_count() - 1) + ")");
    ++returned_frames_;
    if (!openings_) return counted(make_frame());
    const std::size_t window_frames = frames_to_open(timeline_.frames_per_step);
    while (ahead_.size() < window_frames && made_frames_ < timeline_.frame_count()) {
        const Frame made = make_frame();
        ahead_.push_back({made.time_step, *made.values, *made.flags, made.values_changed});
    }
    current_ = std::move(ahead_.front());
    ahead_.pop_front();
    window_.assign(1, &current_.flags);
    for (std::size_t k = 0; k + 1 < window_frames && k < ahead_.size(); ++k) window_.push_back(&ahead_[k].flags);
    openings_->next(window_);
    Frame frame;
    frame.time_step = current_.time_step;
    frame.values = &current_.values;
    frame.flags = &current_.flags;
    frame.values_changed = current_.values_changed;
    frame.openings = &openings_->openings();
    return counted(frame);
}

CoherentSequence::Frame CoherentSequence::make_frame() {
    const std::size_t frame = made_frames_++;
    const StepBlend blend = blend_at(timeline_, frame, coherence_);
    Frame result;
    result.time_step = timeline_.time_step(frame);
    result.openings = &no_openings_;
    const bool new_step = lower_step_ != blend.lower;
    if (new_step) advance_to(blend.lower);
    if (blend.weight == 0.0f) {
        result.values = &lower_;
        result.flags = &was_;
        // Held steps (none between report steps) change nothing.
        result.values_changed = new_step || coherence_ == Coherence::smooth;
        return result;
    }
    transition_.values_at(blend.weight, lower_, upper_, blended_);
    transition_.flags_at(blend.weight, was_, is_, flags_);
    result.values = &blended_;
    result.flags = &flags_;
    return result;
}

}  // namespace cutaway::temporal
