#pragma once
// The render size while the view moves (dragging, wheel, a script's `drag on`): a cutaway frame
// costs about its pixel count, so the viewer draws smaller frames while the camera turns and the
// full size once it stops, as ParaView and VTK's interactors do. The factor adapts to the frames
// measured at it: the median of the last few (one slow frame on this shared machine is noise, not
// a reason to shrink) one step smaller when slower than the target rate, one step larger when
// the larger size is predicted (at the pixel ratio, which over-predicts: part of a frame does not
// scale with pixels) to stay within it.
#include <cstddef>

#include "viewer/rolling_median.h"

namespace cutaway::viewer {

class InteractionResolution {
public:
    /// Factors of the render size it steps through, largest first.
    static constexpr float factors[] = {1.0f, 0.85f, 0.7f, 0.6f, 0.5f, 0.42f, 0.35f, 0.3f, 0.25f};
    static constexpr std::size_t start_level = 4;  ///< 0.5: a quarter of the pixels
    /// Frames at one factor before it may change, and the most its median is taken over.
    static constexpr std::size_t frames_to_decide = 2, frames_kept = 3;

    /// The render size factor for frames drawn while the view moves.
    float factor() const { return factors[level_]; }
    /// After a frame drawn at factor() while the view moved: `frame_ms`, the whole viewer loop
    /// pass that drew it; `target_fps` > 0.
    void frame_drawn(double frame_ms, double target_fps);

private:
    void step_to(std::size_t level);

    std::size_t level_ = start_level;
    RollingMedian recent_ms_{frames_kept};  ///< the last frames at this level
};

}  // namespace cutaway::viewer
