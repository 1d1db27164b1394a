#pragma once
// stats.json summaries of `cutaway animate` from its per-frame entries: pop_max, pop_reversals_total
// (cells turning back: temporal_metrics.h PopReversals), cut_flicker_max,
// primary_exposure_min, context_share_mean (the mean over frames of the share of model pixels
// showing the context's own surface), the median frame time and, when the frames were timed against render,
// frame_over_render.
#include <nlohmann/json.hpp>

namespace cutaway::app {

/// `frames`: one object per frame with `ms`, and from frame 1 on `pop_in`, `pop_out`, `pop_reversals`; with metrics
/// `cut_flicker` (from frame 1) and `primary_exposure` (null when the frame had no primary pixel);
/// with `render_ms` when timed against render. `encoder_finish_ms`: ffmpeg's work after the last
/// frame, counted on the animation's side of frame_over_render (frames 1.. against the same
/// frames drawn again: frame 0 warms up, as render's --warmup frame). A summary nothing supports is null
/// with KEY_absent saying why.
void put_frame_summaries(nlohmann::json& stats, const nlohmann::json& frames, double encoder_finish_ms);

}  // namespace cutaway::app
