#pragma once
// The per-stage timing overlay: rolling medians of fenced stage times, frame time and rate.
#include "viewer/frame_timings.h"

namespace cutaway::viewer {

void draw_timing_overlay(const FrameTimings& timings);

}  // namespace cutaway::viewer
