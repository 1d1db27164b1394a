#include "app/animation_summary.h"

#include <algorithm>
#include <string>
#include <vector>

#include "app_core/render_report.h"
#include "metrics/median.h"

namespace cutaway::app {
namespace {

using nlohmann::json;

/// The extreme of `key` over the frames that have it as a number (`larger`: max, else min), or
/// null with KEY_absent = `why_absent` when none has.
void put_extreme(json& stats, const std::string& name, const json& frames, const char* key, bool larger,
                 const char* why_absent) {
    json best = nullptr;
    for (const json& frame : frames) {
        if (!frame.contains(key) || !frame[key].is_number()) continue;
        const double value = frame[key].get<double>();
        if (best.is_null() || (larger ? value > best.get<double>() : value < best.get<double>())) best = frame[key];
    }
    stats[name] = best;
    if (best.is_null()) stats[name + "_absent"] = why_absent;
}

}  // namespace

void put_frame_summaries(json& stats, const json& frames, double encoder_finish_ms) {
    json pops = json::array();
    std::size_t reversals = 0;
    for (const json& frame : frames) {
        if (frame.contains("pop_in")) pops.push_back({{"pop", frame["pop_in"].get<double>() + frame["pop_out"].get<double>()}});
        reversals += frame.value("pop_reversals", std::size_t(0));
    }
    put_extreme(stats, "pop_max", pops, "pop", true, "one frame: no frame before it");
    if (stats["pop_max"].is_number()) stats["pop_max"] = stats["pop_max"].get<std::size_t>();
    stats["pop_reversals_total"] = reversals;
    put_extreme(stats, "cut_flicker_max", frames, "cut_flicker", true, "one frame, or --no-metrics");
    put_extreme(stats, "primary_exposure_min", frames, "primary_exposure", false,
                "--no-metrics, or no frame has a primary pixel");
    std::vector<double> shares;
    for (const json& frame : frames)
        if (frame.contains("context_share")) shares.push_back(frame["context_share"].get<double>());
    if (shares.empty()) {
        stats["context_share_mean"] = nullptr;
        stats["context_share_mean_absent"] = "--no-metrics";
    } else {
        double sum = 0;
        for (double share : shares) sum += share;
        stats["context_share_mean"] = sum / double(shares.size());
    }
    std::vector<double> frame_ms;
    for (const json& frame : frames) frame_ms.push_back(frame["ms"].get<double>());
    stats["frame_ms_median"] = metrics::median(frame_ms);
    if (!frames.empty() && frames[0].contains("render_ms")) {
        // The same frames drawn again as `render` draws them (no upload, read-back or encoding).
        // Frame 0 warms up (shaders, buffers) as render's --warmup frame does: left out of both.
        double animate_ms = encoder_finish_ms, render_ms = 0;
        for (std::size_t f = frames.size() > 1 ? 1 : 0; f < frames.size(); ++f) {
            animate_ms += frames[f]["ms"].get<double>();
            render_ms += frames[f]["render_ms"].get<double>();
        }
        stats["frame_over_render"] = animate_ms / render_ms;
    }
}

}  // namespace cutaway::app
