#pragma once
// The per-stage timing overlay: rolling medians of fenced stage times, frame time and rate.
#include <imgui.h>

#include "viewer/frame_timings.h"

namespace cutaway::viewer {

/// Draws the overlay at the window's bottom left, under the control panel (which leaves it room:
/// the model is framed right of both, so the overlay covers none of it). Returns its size, pixels.
ImVec2 draw_timing_overlay(const FrameTimings& timings);

}  // namespace cutaway::viewer
