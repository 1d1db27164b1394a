#pragma once
// The per-stage timing overlay: rolling medians of fenced stage times, frame time and rate.
#include "viewer/frame_timings.h"

namespace cutaway::viewer {

/// Draws the overlay at the window's bottom right, left of the colour bar: `colour_bar_share` is
/// the share of the window's width the bar keeps at the right edge (0 without one), so no text of
/// the overlay covers the bar's labels.
void draw_timing_overlay(const FrameTimings& timings, float colour_bar_share);

}  // namespace cutaway::viewer
