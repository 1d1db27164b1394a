#pragma once
// The frames of an animation over report steps, in order: each frame's values (the colouring)
// and primary flags under a coherence mode (coherence.h). Reads each report step from its source
// once. Under smooth, frames are made frames_to_open - 1 ahead of the one returned, so that the
// cuts of cells about to enter open before they do (CellOpenings). No OpenGL here.
#include <cstddef>
#include <cstdint>
#include <deque>
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
        /// One per Eclipse cell, 1 = selected by the coherence mode in this frame (drawn as a
        /// primary).
        const std::vector<std::uint8_t>* flags = nullptr;
        bool values_changed = true;   ///< false: the same values as the frame before
        std::size_t primary_cells = 0;  ///< flags set
        /// Under smooth, the cells whose cut is opening (they enter within frames_to_open - 1
        /// frames) or closing (they left); empty under none.
        const std::vector<OpeningCell>* openings = nullptr;
    };
    /// The next frame (0, 1, ... timeline.frame_count() - 1); the pointers stay valid until the
    /// next call. Throws std::logic_error past the last frame.
    Frame next();

    /// Report steps read from the source so far.
    std::size_t steps_read() const { return steps_read_; }

    /// Per-cell bytes the sequence holds at most besides the model (values at two steps and
    /// between them, the transition's two times, flags at the steps and between them, the frames
    /// kept ahead and the one returned, and the openings' levels).
    static constexpr std::size_t bytes_per_cell = 5 * 4 + 3 + (CellOpenings::max_frames_to_open + 1) * 5 + 1;

private:
    /// A frame made ahead of the one returned (smooth), its arrays its own.
    struct AheadFrame {
        double time_step = 0;
        std::vector<float> values;
        std::vector<std::uint8_t> flags;
        bool values_changed = true;
    };
    /// The next frame in order as the coherence mode makes it, without openings; the pointers
    /// stay valid until the next call.
    Frame make_frame();
    /// Makes `lower_` hold report step `step` and, under smooth, `upper_` the step after it with
    /// the transition between them.
    void advance_to(std::size_t step);
    std::vector<float> read(std::size_t step);
    /// Counts the frame's primaries.
    static Frame counted(Frame frame);

    const StepValueSource& source_;
    AnimationTimeline timeline_;
    Coherence coherence_;
    grid::PrimaryRange range_;
    float band_;
    PrimaryTracker tracker_;  ///< memberships at report steps, in step order
    std::size_t made_frames_ = 0, returned_frames_ = 0;
    std::optional<std::size_t> lower_step_, upper_step_;
    std::vector<float> lower_, upper_, blended_;
    std::vector<std::uint8_t> was_, is_, flags_;  ///< flags at the lower and upper steps, and between
    PacedTransition transition_;
    std::optional<CellOpenings> openings_;  ///< smooth only
    std::deque<AheadFrame> ahead_;          ///< smooth: frames made, not yet returned
    AheadFrame current_;                    ///< smooth: the frame returned last
    std::vector<const std::vector<std::uint8_t>*> window_;  ///< the openings' window (smooth)
    std::vector<OpeningCell> no_openings_;
    std::size_t steps_read_ = 0;
};

}  // namespace cutaway::temporal
