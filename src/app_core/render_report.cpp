#include "app_core/render_report.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "metrics/median.h"

namespace cutaway::app {
using metrics::median;

using nlohmann::json;

json stage_statistics(const std::vector<pipeline::FrameTimes>& runs, const std::vector<std::string>& extra_stages) {
    json wall = json::object(), query = json::object(), valid = json::object();
    std::vector<std::string> names(std::begin(pipeline::stage_names), std::end(pipeline::stage_names));
    names.insert(names.end(), extra_stages.begin(), extra_stages.end());
    names.push_back("total");
    for (const std::string& name : names) {
        std::vector<double> walls, queries;
        bool all_valid = true;
        for (const pipeline::FrameTimes& run : runs) {
            const gl::StageTime* found = name == "total" ? &run.total : nullptr;
            for (const gl::StageTime& stage : run.stages)
                if (stage.stage == name) found = &stage;
            walls.push_back(found ? found->wall_ms : 0.0);
            queries.push_back(found ? found->gl_query_ms : 0.0);
            all_valid = all_valid && (!found || found->gl_query_valid);
        }
        wall[name] = median(walls);
        query[name] = median(queries);
        valid[name] = all_valid;
    }
    json all_runs = json::array();
    for (const pipeline::FrameTimes& run : runs) all_runs.push_back(run.total.wall_ms);
    return {{"stages_ms", wall}, {"gl_query_ms", query}, {"gl_query_valid_by_stage", valid},
            {"gl_query_valid", std::all_of(valid.begin(), valid.end(), [](const json& v) { return v.get<bool>(); })},
            {"total_ms_per_run", all_runs}};
}

json strategy_json(const pipeline::CutSurfaceEntry& drawn, const std::string& requested, std::uint64_t auto_sweep_from) {
    json out = {{"name", drawn.name}, {"device", drawn.device}, {"why", drawn.why}, {"requested", requested}};
    if (requested == pipeline::auto_cut_strategy) {
        out["chosen_by"] = pipeline::auto_choice_rule(auto_sweep_from);
        out["auto_sweep_from_primaries"] = auto_sweep_from;
    }
    return out;
}

json faces_drawn_json(const pipeline::FacesDrawn& drawn) {
    json faces = {{"secondary", drawn.secondary}, {"primary", drawn.primary}, {"shell_contours", drawn.shell_contours}};
    if (drawn.culling) {
        const pipeline::CullingCounts& c = *drawn.culling;
        faces["culling"] = {{"bricks", c.bricks}, {"bricks_culled", c.bricks_culled}, {"cells_culled", c.cells_culled},
                            {"cells_behind_cut", c.cells_behind}, {"cells_straddling_cut", c.cells_straddling},
                            {"faces_selected", c.faces_requested}};
    }
    return faces;
}

void put_metric(json& stats, const std::string& key, double fraction, std::size_t denominator, const std::string& why_absent) {
    if (denominator > 0) {
        stats[key] = fraction;
        return;
    }
    stats[key] = nullptr;
    stats[key + "_absent"] = why_absent;
}

std::vector<io::NamedFile> render_outputs(const RenderOptions& options) {
    return {{"--out", options.out}, {"--cell-ids", options.cell_ids}, {"--stats", options.stats}};
}

void refuse_render_overwrites(const RenderOptions& options) {
    refuse_overwrites(model_input_files(options.model), render_outputs(options));
}

void check_view(const pipeline::ModelFrame& frame, const RenderOptions& options) {
    const glm::vec3 extent = frame.render_max - frame.render_min;
    const bool finite = std::isfinite(extent.x) && std::isfinite(extent.y) && std::isfinite(extent.z) &&
                        std::isfinite(frame.radius());
    if (!finite || !(std::max(extent.x, extent.y) > 0))
        throw std::invalid_argument(
            options.model.front() + ": expected a model with a finite, non-zero horizontal extent in single precision " +
            "(render units), found " + number_text(extent.x) + " x " + number_text(extent.y) + " x " + number_text(extent.z));
    // Beyond this distance the model's radius spans less than a pixel of the frame's height: an
    // empty frame (the cut camera alone may be that far: it draws no pixel of its own).
    const double farthest = frame.radius() * 0.5 * options.height / std::tan(0.5 * double(glm::radians(pipeline::default_fovy_deg)));
    for (const auto& [option, pose] : {std::pair{"--camera", std::optional(options.camera_pose())},
                                       std::pair{"--freeze-camera", options.freeze_pose}}) {
        if (pose && pose->distance > 0 && pose->distance < frame.radius())
            throw std::invalid_argument(std::string(option) + ": expected DIST 0 (frame the model) or at least the model's radius " +
                                        number_text(frame.radius()) + " (outside it), found " + number_text(pose->distance));
        if (pose && std::string(option) == "--camera" && pose->distance > farthest)
            throw std::invalid_argument("--camera: expected DIST 0 (frame the model) or at most " + number_text(farthest) +
                                        " (farther, the model covers under a pixel), found " + number_text(pose->distance));
    }
}

void refuse_nothing_to_draw(const RenderOptions& options, std::size_t primary_count, const std::string& selected_name,
                            const grid::PrimaryRange& range) {
    if (primary_count == 0 && options.frame_settings().only == pipeline::OnlyLayer::primaries)
        throw std::invalid_argument("--only primaries: expected primary cells to draw, found no cell of " + selected_name +
                                    " in the primary range [" + number_text(range.min) + ", " + number_text(range.max) + "]");
}

}  // namespace cutaway::app
