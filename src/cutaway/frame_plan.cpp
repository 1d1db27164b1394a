#include "cutaway/frame_plan.h"

#include <algorithm>

namespace cutaway::pipeline {
namespace {

struct PassInfo {
    FramePass pass;
    const char* name;
};

constexpr PassInfo pass_names[] = {
    {FramePass::clear_cut, "clear_cut"},
    {FramePass::strategy_cut, "strategy_cut"},
    {FramePass::volume_cut, "volume_cut"},
    {FramePass::opening_cut, "opening_cut"},
    {FramePass::rear_shell, "rear_shell"},
    {FramePass::combine_cut, "combine_cut"},
    {FramePass::resolve_cut, "resolve_cut"},
    {FramePass::filter_resolve_cut, "filter_resolve_cut"},
    {FramePass::culling, "culling"},
    {FramePass::secondary_list, "secondary_list"},
    {FramePass::view_rear_shell, "view_rear_shell"},
    {FramePass::clear_scene, "clear_scene"},
    {FramePass::secondaries, "secondaries"},
    {FramePass::bind_scene, "bind_scene"},
    {FramePass::primaries, "primaries"},
    {FramePass::hidden_primary_walls, "hidden_primary_walls"},
    {FramePass::wells, "wells"},
    {FramePass::shell_contours, "shell_contours"},
    {FramePass::reset_depth_test, "reset_depth_test"},
    {FramePass::combine_scene, "combine_scene"},
    {FramePass::ssao, "ssao"},
    {FramePass::composite, "composite"},
    {FramePass::colour_bar, "colour_bar"},
    {FramePass::well_labels, "well_labels"},
    {FramePass::caption, "caption"},
};

/// Stage 1 and what follows it: the strategy's cut, the distributed max, the mean filter; the cut
/// is resolved (normals, clamp) at the end of whichever of them runs last.
void plan_cut(const FrameSettings& s, const RendererState& state, FramePlan& plan) {
    const bool filtered = plan.cut_drawn && s.mean_filter >= 3;
    const bool combined = plan.combine_seeds || plan.combine_cut_depth;
    PlannedStage cut{"cut_surface", {FramePass::clear_cut}};
    if (plan.cut_drawn) {
        // Without a primary set (--primaries none) the volumes alone cut.
        if (s.primaries) cut.passes.push_back(FramePass::strategy_cut);
        if (state.cut_volumes) cut.passes.push_back(FramePass::volume_cut);
        // The seed strategies draw the opening cells among their seeds, inside strategy_cut.
        if (state.opening_cells && !(state.cone_field_strategy && s.primaries)) cut.passes.push_back(FramePass::opening_cut);
        if (plan.clamp_to_rear_shell) cut.passes.push_back(FramePass::rear_shell);
        if (!combined && !filtered) cut.passes.push_back(FramePass::resolve_cut);
    }
    plan.stages.push_back(cut);
    if (combined) {
        PlannedStage combine{"cut_combine", {}};
        if (plan.combine_cut_depth || plan.combine_rear_shell) combine.passes.push_back(FramePass::combine_cut);
        if (!filtered) combine.passes.push_back(FramePass::resolve_cut);
        plan.stages.push_back(combine);
    }
    if (filtered) plan.stages.push_back({"mean_filter", {FramePass::filter_resolve_cut}});
}

/// Stage 2's faces and the secondaries themselves.
void plan_secondaries(const FrameSettings& s, FramePlan& plan) {
    if (plan.cut_needed && s.draw == DrawMode::visible) plan.stages.push_back({"culling", {FramePass::culling}});
    if (plan.cut_needed && s.draw == DrawMode::all_faces) plan.stages.push_back({"", {FramePass::secondary_list}});
    PlannedStage secondary{"secondary", {}};
    if (plan.clip_view_rear_shell) secondary.passes.push_back(FramePass::view_rear_shell);
    secondary.passes.push_back(FramePass::clear_scene);
    if (plan.cut_needed) secondary.passes.push_back(FramePass::secondaries);
    plan.stages.push_back(secondary);
}

/// Stage 3, the distributed composite and the screen-space passes.
void plan_primaries_and_post(const FrameSettings& s, const RendererState& state, FramePlan& plan) {
    PlannedStage primary{"primary", {FramePass::bind_scene}};
    if (plan.draw_primaries) primary.passes.push_back(FramePass::primaries);
    if (s.only == OnlyLayer::secondaries && s.primaries) primary.passes.push_back(FramePass::hidden_primary_walls);
    if (state.wells) primary.passes.push_back(FramePass::wells);
    if (s.contours) primary.passes.push_back(FramePass::shell_contours);
    primary.passes.push_back(FramePass::reset_depth_test);
    plan.stages.push_back(primary);
    if (state.distributed) plan.stages.push_back({"composite", {FramePass::combine_scene}});
    if (!state.screen_passes) return;
    if (s.ssao) plan.stages.push_back({"ssao", {FramePass::ssao}});
    PlannedStage post{"post", {FramePass::composite}};
    if (s.colour_bar) post.passes.push_back(FramePass::colour_bar);
    if (state.wells) post.passes.push_back(FramePass::well_labels);
    if (!s.caption.empty()) post.passes.push_back(FramePass::caption);
    plan.stages.push_back(post);
}

}  // namespace

const char* to_string(FramePass pass) {
    for (const PassInfo& info : pass_names)
        if (info.pass == pass) return info.name;
    return "unknown";
}

PassTargets targets_of(FramePass pass, const FramePlan& plan) {
    const std::uint32_t clamp = plan.clamp_to_rear_shell ? target_rear_shell : 0;
    switch (pass) {
    case FramePass::clear_cut: return {0, target_cut_depth | target_cut_surface};
    case FramePass::strategy_cut:
    case FramePass::volume_cut:
    case FramePass::opening_cut: return {0, target_cut_depth};
    case FramePass::rear_shell: return {0, target_rear_shell};
    case FramePass::combine_cut: {
        const std::uint32_t images = (plan.combine_cut_depth ? target_cut_depth : 0) | (plan.combine_rear_shell ? target_rear_shell : 0);
        return {images, images};
    }
    case FramePass::resolve_cut:
    case FramePass::filter_resolve_cut: return {target_cut_depth | clamp, target_cut_surface};
    case FramePass::culling: return {plan.cut_drawn ? target_cut_surface : 0u, target_faces};
    case FramePass::secondary_list: return {0, target_faces};
    case FramePass::view_rear_shell: return {0, target_rear_shell};
    case FramePass::clear_scene: return {0, target_scene};
    case FramePass::secondaries:
        return {target_faces | target_cut_surface | (plan.clip_view_rear_shell ? target_rear_shell : 0), target_scene};
    case FramePass::bind_scene:
    case FramePass::reset_depth_test: return {};
    case FramePass::primaries:
    case FramePass::hidden_primary_walls:
    case FramePass::wells: return {0, target_scene};
    case FramePass::shell_contours:
    case FramePass::combine_scene: return {target_scene, target_scene};
    case FramePass::ssao: return {target_scene, target_occlusion};
    case FramePass::composite:
        return {target_scene | (plan.runs(FramePass::ssao) ? target_occlusion : 0), target_final};
    case FramePass::colour_bar:
    case FramePass::well_labels:
    case FramePass::caption: return {target_final, target_final};
    }
    return {};
}

bool FramePlan::runs(FramePass pass) const {
    return std::any_of(stages.begin(), stages.end(), [&](const PlannedStage& stage) {
        return std::find(stage.passes.begin(), stage.passes.end(), pass) != stage.passes.end();
    });
}

std::vector<std::string> FramePlan::describe() const {
    std::vector<std::string> lines;
    for (const PlannedStage& stage : stages) {
        std::string line = (stage.stage.empty() ? std::string("untimed") : stage.stage) + ":";
        for (FramePass pass : stage.passes) line += std::string(" ") + to_string(pass);
        lines.push_back(line);
    }
    return lines;
}

FramePlan plan_frame(const FrameSettings& s, const RendererState& state) {
    FramePlan plan;
    plan.cut_needed = s.only != OnlyLayer::primaries;
    plan.draw_primaries = s.only != OnlyLayer::secondaries && s.primaries;
    plan.cut_drawn = plan.cut_needed && s.cut_enabled;
    plan.clamp_to_rear_shell = !s.see_through;
    plan.makes_cut = !(state.frozen && state.frozen_cut_valid);
    const bool combined = plan.cut_drawn && state.distributed;
    // Cone-field strategies combine their seeds (inside stage 1, before the transform); the
    // others their cut. A max either way.
    // Every renderer draws the same cut volumes, so seeds combined before them suffice.
    const bool seeds = state.cone_field_strategy && s.primaries;
    plan.combine_seeds = combined && seeds;
    plan.combine_cut_depth = combined && !seeds;
    plan.combine_rear_shell = combined && plan.clamp_to_rear_shell;
    plan.clip_view_rear_shell = plan.cut_drawn && state.frozen && plan.clamp_to_rear_shell;
    if (plan.makes_cut) plan_cut(s, state, plan);
    plan_secondaries(s, plan);
    plan_primaries_and_post(s, state, plan);
    return plan;
}

std::string first_unwritten_read(const FramePlan& plan) {
    // A kept frozen cut was written by an earlier frame.
    std::uint32_t written = plan.makes_cut ? 0u : target_cut_depth | target_cut_surface | target_rear_shell;
    for (const PlannedStage& stage : plan.stages)
        for (FramePass pass : stage.passes) {
            const PassTargets targets = targets_of(pass, plan);
            if (const std::uint32_t missing = targets.reads & ~written)
                return std::string(to_string(pass)) + " reads target " + std::to_string(missing) + " before any pass writes it";
            written |= targets.writes;
        }
    return {};
}

}  // namespace cutaway::pipeline
