#pragma once
// The frames of an animation over report steps, in order: each frame's values (the colouring)
// and primary flags under a coherence mode (coherence.h). Reads each report step from its source
// once. No OpenGL here.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "cutaway/temporal/coherence.h"
#include "cutaway/temporal/cell_openings.h"
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
        /// One per Eclipse cell, 1 = drawn as a primary: under none the selection; under smooth
        /// the selection of frames_to_open - 1 frames before, each cell once its cut is open
        /// (CellOpenings over frames_to_open(frames_per_step) frames).
        const std::vector<std::uint8_t>* flags = nullptr;
        /// One per Eclipse cell, 1 = selected by the coherence mode in this frame.
        const std::vector<std::uint8_t>* selected = nullptr;
        bool values_changed = true;   ///< false: the same values as the frame before
        std::size_t primary_cells = 0;  ///< flags set
        /// Under smooth, the cells whose cut is opening or closing; empty under none.
        const std::vector<OpeningCell>* openings = nullptr;
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
    /// Under smooth, holds back the selected cells whose cut is still opening; counts the primaries.
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
    std::optional<CellOpenings> openings_;  ///< smooth only
    std::vector<std::uint8_t> drawn_;       ///< the frame's drawn flags (smooth)
    std::vector<OpeningCell> no_openings_;
    std::size_t steps_read_ = 0;
};

}  // namespace cutaway::temporal
