#pragma once
// Frame and stage times of the viewer: rolling medians for the overlay, and one record per frame
// for `--stats` (the responsiveness measurement).
#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cutaway/cutaway_renderer.h"
#include "viewer/rolling_median.h"

namespace cutaway::viewer {

/// One pass of the viewer loop as --stats records it.
struct LoopPass {
    double loop_ms = 0;        ///< wall clock: events, script, panel, render if needed, blit, swap
    bool rendered = false;     ///< a cutaway frame was drawn in it
    int render_width = 0;      ///< of the frame drawn (0 when none was)
    int render_height = 0;
    bool view_moving = false;  ///< drawn while the view moved (interaction_resolution.h)
};

struct StageMedian {
    double wall_ms = 0;       ///< rolling median of the fenced wall-clock time
    double gl_query_ms = 0;   ///< rolling median of GL_TIME_ELAPSED
    bool gl_query_valid = false;  ///< of the last frame
};

class FrameTimings {
public:
    explicit FrameTimings(std::size_t window);

    /// A cutaway frame was rendered with these fenced stage times.
    void add_render(const pipeline::FrameTimes& times);
    /// One pass of the viewer loop (events, render if needed, panel, swap).
    void add_loop(const LoopPass& pass);

    /// Stage names in pipeline order, then "total".
    std::vector<std::string> stage_order() const;
    StageMedian stage(const std::string& name) const;
    /// Rolling medians of whole loop passes, with and without a cutaway frame in them.
    double loop_ms_rendering() const { return loop_rendering_.median(); }
    double loop_ms_idle() const { return loop_idle_.median(); }
    std::size_t frames() const { return records_.size(); }
    std::size_t window() const { return window_; }

    /// Per-frame records and medians over the whole run (not only the window).
    nlohmann::json to_json() const;

private:
    struct StageTrack {
        RollingMedian wall, query;
        bool valid = false;
    };
    struct Record {
        LoopPass pass;
        std::map<std::string, double> stage_ms;
    };
    std::size_t window_;
    std::map<std::string, StageTrack> stages_;
    RollingMedian loop_rendering_, loop_idle_;
    std::map<std::string, double> pending_;  ///< stage times of the frame being assembled
    std::vector<Record> records_;
};

}  // namespace cutaway::viewer
