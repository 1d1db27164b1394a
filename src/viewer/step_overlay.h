#pragma once
// The date of the shown report step, drawn over the top right of the frame (a dynamic property only).
#include <string>

namespace cutaway::viewer {

/// Draws `caption` (step_clock.h step_caption) at the top right of the window, left of the share
/// of its width the colour bar keeps, on a dark band so it reads over any colour; nothing when it
/// is empty.
void draw_step_overlay(const std::string& caption, float colour_bar_share);

}  // namespace cutaway::viewer
