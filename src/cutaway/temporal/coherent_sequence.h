#pragma once
// The frames of an animation over report steps, in order: each frame's values (the colouring)
// and primary flags under a coherence mode (coherence.h). Reads each report step from its source
// once. No OpenGL here.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "cutaway/temporal/coherence.h"
#include "cutaway/temporal/cut_opening.h"
#include "cutaway/temporal/paced_transition.h"
#include "cutaway/temporal/primary_tracker.h"
#include "cutaway/temporal/step_values.h"

namespace cutaway::temporal {

class CoherentSequence {
public:
    /// `range`: the primary range; `band`: its hysteresis widening in property units (smooth;
    /// `none` selects anew at each step whatever the band). `grid` and `source` must outlive it.
    CoherentSequence(const grid::CornerPointGrid& grid, const StepValueSource& source, const AnimationTimeline& timeline,
                     Coherence coherence, const grid::PrimaryRange& range, float band,
                     const std::optional<grid::IjkBox>& box = std::nullopt);

    struct Frame {
        double time_step = 0;                      ///< fractional report step
        const std::vector<float>* values = nullptr;  ///< one per Eclipse cell
        const std::vector<std::uint8_t>* flags = nullptr;  ///< one per Eclipse cell, 1 = primary
        bool values_changed = true;   ///< false: the same values as the frame before
        std::size_t primary_cells = 0;  ///< flags set
        /// How far the cut is open (opened_aperture_deg): 1 under none; under smooth the cut opens
        /// at a bounded speed where primaries appear from none (CutOpening, one report step's
        /// frames to open).
        float cut_opening = 1;
    };
    /// The next frame (0, 1, ... timeline.frame_count() - 1); the pointers stay valid until the
    /// next call. Throws std::logic_error past the last frame.
    Frame next();

    /// Report steps read from the source so far.
    std::size_t steps_read() const { return steps_read_; }

private:
    /// Makes `lower_` hold report step `step` and, under smooth, `upper_` the step after it with
    /// the transition between them.
    void advance_to(std::size_t step);
    std::vector<float> read(std::size_t step);
    /// Counts the frame's primaries and sets its cut opening.
    Frame finished(Frame frame);

    const StepValueSource& source_;
    AnimationTimeline timeline_;
    Coherence coherence_;
    grid::PrimaryRange range_;
    float band_;
    PrimaryTracker tracker_;  ///< memberships at report steps, in step order
    std::size_t next_frame_ = 0;
    std::optional<std::size_t> lower_step_, upper_step_;
    std::vector<float> lower_, upper_, blended_;
    std::vector<std::uint8_t> was_, is_, flags_;  ///< flags at the lower and upper steps, and between
    PacedTransition transition_;
    std::optional<CutOpening> opening_;  ///< smooth only
    std::size_t steps_read_ = 0;
};

}  // namespace cutaway::temporal
