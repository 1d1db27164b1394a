#include "viewer/frame_timings.h"

#include <algorithm>

#include "metrics/median.h"

namespace cutaway::viewer {

FrameTimings::FrameTimings(std::size_t window) : window_(window), loop_rendering_(window), loop_idle_(window) {}

void FrameTimings::add_render(const pipeline::FrameTimes& times) {
    std::vector<const gl::StageTime*> all;
    for (const gl::StageTime& stage : times.stages) all.push_back(&stage);
    all.push_back(&times.total);
    for (const gl::StageTime* stage : all) {
        const std::string name = stage == &times.total ? "total" : stage->stage;
        auto [track, inserted] = stages_.try_emplace(name, StageTrack{RollingMedian(window_), RollingMedian(window_)});
        track->second.wall.add(stage->wall_ms);
        track->second.query.add(stage->gl_query_ms);
        track->second.valid = stage->gl_query_valid;
        pending_[name] = stage->wall_ms;
    }
}

void FrameTimings::add_loop(const LoopPass& pass) {
    (pass.rendered ? loop_rendering_ : loop_idle_).add(pass.loop_ms);
    records_.push_back({pass, pass.rendered ? std::move(pending_) : std::map<std::string, double>{}});
    pending_.clear();
}

std::vector<std::string> FrameTimings::stage_order() const {
    std::vector<std::string> order(std::begin(pipeline::stage_names), std::end(pipeline::stage_names));
    order.push_back("total");
    return order;
}

StageMedian FrameTimings::stage(const std::string& name) const {
    const auto found = stages_.find(name);
    if (found == stages_.end()) return {};
    return {found->second.wall.median(), found->second.query.median(), found->second.valid};
}

nlohmann::json FrameTimings::to_json() const {
    nlohmann::json frames = nlohmann::json::array();
    std::vector<double> loops_rendering, loops_idle;
    std::map<std::string, std::vector<double>> stage_runs;
    for (std::size_t i = 0; i < records_.size(); ++i) {
        const Record& r = records_[i];
        nlohmann::json frame = {{"frame", i}, {"rendered", r.pass.rendered}, {"loop_ms", r.pass.loop_ms}, {"stages_ms", r.stage_ms}};
        if (r.pass.rendered) {
            frame["render_size"] = {r.pass.render_width, r.pass.render_height};
            frame["view_moving"] = r.pass.view_moving;
        }
        frames.push_back(frame);
        (r.pass.rendered ? loops_rendering : loops_idle).push_back(r.pass.loop_ms);
        for (const auto& [name, ms] : r.stage_ms) stage_runs[name].push_back(ms);
    }
    nlohmann::json stage_medians = nlohmann::json::object();
    for (const auto& [name, runs] : stage_runs) stage_medians[name] = metrics::median(runs);
    return {{"frames", frames},
            {"rendered_frames", loops_rendering.size()},
            {"idle_frames", loops_idle.size()},
            {"median_loop_ms_rendering", metrics::median(loops_rendering)},
            {"median_loop_ms_idle", metrics::median(loops_idle)},
            {"median_stages_ms", stage_medians}};
}

}  // namespace cutaway::viewer
