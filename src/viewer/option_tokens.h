#pragma once
// `set --border threshold --ssao off` in a viewer script: the tokens are parsed by the same CLI11
// options as `cutaway render` (add_selection_options, add_frame_options), into the live options.
#include <string>
#include <vector>

#include "app_core/render_options.h"

namespace cutaway::viewer {

/// Applies `tokens` to `options` and returns the Change bits they cause (change_selection when a
/// selection option was given). --range clears --primary-fraction and the other way round; a new
/// --property alone starts at its default range (1%) and first step.
/// Throws std::invalid_argument with CLI11's message, or frame_settings()'s, for a bad token or
/// value; `options` is then left unchanged.
unsigned apply_option_tokens(app::RenderOptions& options, const std::vector<std::string>& tokens);

}  // namespace cutaway::viewer
