// The frame plan (src/cutaway/frame_plan.h): which passes run for which settings and renderer
// state, and that every plan reads only what an earlier pass (or a kept frozen cut) wrote.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "cutaway/frame_plan.h"

namespace cutaway::pipeline {
namespace {

std::vector<FramePass> passes_of(const FramePlan& plan, const std::string& stage) {
    for (const PlannedStage& planned : plan.stages)
        if (planned.stage == stage) return planned.passes;
    return {};
}

std::vector<std::string> stage_names(const FramePlan& plan) {
    std::vector<std::string> names;
    for (const PlannedStage& stage : plan.stages) names.push_back(stage.stage);
    return names;
}

TEST(FramePlan, PaperDefaultsRunEveryStageOnce) {
    const FramePlan plan = plan_frame(FrameSettings{}, RendererState{});
    EXPECT_EQ(stage_names(plan),
              (std::vector<std::string>{"cut_surface", "mean_filter", "culling", "secondary", "primary", "ssao", "post"}));
    // The 9x9 mean filter resolves the cut: stage 1 leaves it unresolved.
    EXPECT_EQ(passes_of(plan, "cut_surface"),
              (std::vector<FramePass>{FramePass::clear_cut, FramePass::strategy_cut, FramePass::rear_shell}));
    EXPECT_EQ(passes_of(plan, "mean_filter"), std::vector<FramePass>{FramePass::filter_resolve_cut});
    EXPECT_EQ(first_unwritten_read(plan), "");
}

TEST(FramePlan, UnfilteredCutIsResolvedInStageOne) {
    FrameSettings s;
    s.mean_filter = 0;
    const FramePlan plan = plan_frame(s, RendererState{});
    EXPECT_FALSE(plan.runs(FramePass::filter_resolve_cut));
    EXPECT_EQ(passes_of(plan, "cut_surface").back(), FramePass::resolve_cut);
}

TEST(FramePlan, SeeThroughDrawsNoRearShell) {
    FrameSettings s;
    s.see_through = true;
    const FramePlan plan = plan_frame(s, RendererState{});
    EXPECT_FALSE(plan.runs(FramePass::rear_shell));
    EXPECT_EQ(first_unwritten_read(plan), "");
}

TEST(FramePlan, FrozenViewKeepsItsCutAndClipsAgainstTheViewsRearShell) {
    RendererState frozen;
    frozen.frozen = true;
    const FramePlan first = plan_frame(FrameSettings{}, frozen);  // the frozen camera's cut is made once
    EXPECT_TRUE(first.makes_cut);
    frozen.frozen_cut_valid = true;
    const FramePlan later = plan_frame(FrameSettings{}, frozen);
    EXPECT_FALSE(later.makes_cut);
    EXPECT_FALSE(later.runs(FramePass::strategy_cut));
    EXPECT_EQ(passes_of(later, "secondary").front(), FramePass::view_rear_shell);
    EXPECT_EQ(first_unwritten_read(later), "");  // the kept cut counts as written
}

TEST(FramePlan, DistributedFramesCombineCutOrSeedsAndRunScreenPassesOnce) {
    RendererState rank;
    rank.distributed = true;
    rank.screen_passes = false;
    const FramePlan frustum = plan_frame(FrameSettings{}, rank);
    EXPECT_TRUE(frustum.combine_cut_depth);
    EXPECT_EQ(passes_of(frustum, "cut_combine"), std::vector<FramePass>{FramePass::combine_cut});
    EXPECT_TRUE(frustum.runs(FramePass::combine_scene));
    EXPECT_FALSE(frustum.runs(FramePass::ssao));
    EXPECT_FALSE(frustum.runs(FramePass::composite));
    rank.cone_field_strategy = true;
    FrameSettings see_through;
    see_through.see_through = true;
    see_through.mean_filter = 0;
    const FramePlan seeds = plan_frame(see_through, rank);
    EXPECT_TRUE(seeds.combine_seeds);
    // Seeds combined inside stage 1 and no rear shell: nothing left to combine but the resolve.
    EXPECT_EQ(passes_of(seeds, "cut_combine"), std::vector<FramePass>{FramePass::resolve_cut});
    EXPECT_EQ(first_unwritten_read(seeds), "");
}

TEST(FramePlan, OnlyPrimariesDrawsNoCutAndNoSecondaries) {
    FrameSettings s;
    s.only = OnlyLayer::primaries;
    const FramePlan plan = plan_frame(s, RendererState{});
    EXPECT_FALSE(plan.runs(FramePass::strategy_cut));
    EXPECT_FALSE(plan.runs(FramePass::secondaries));
    EXPECT_FALSE(plan.runs(FramePass::culling));
    EXPECT_TRUE(plan.runs(FramePass::primaries));
}

TEST(FramePlan, CutVolumesDrawIntoTheCutAfterThePrimaries) {
    RendererState volumes;
    volumes.cut_volumes = true;
    const FramePlan plan = plan_frame(FrameSettings{}, volumes);
    EXPECT_EQ(passes_of(plan, "cut_surface"), (std::vector<FramePass>{FramePass::clear_cut, FramePass::strategy_cut,
                                                                     FramePass::volume_cut, FramePass::rear_shell}));
    EXPECT_EQ(first_unwritten_read(plan), "");
    // Without volumes the pass is not planned.
    EXPECT_FALSE(plan_frame(FrameSettings{}, RendererState{}).runs(FramePass::volume_cut));
    // Freeze view keeps the volumes' cut with the primaries'.
    volumes.frozen = volumes.frozen_cut_valid = true;
    EXPECT_FALSE(plan_frame(FrameSettings{}, volumes).runs(FramePass::volume_cut));
}

TEST(FramePlan, PrimariesNoneCutsByVolumesAloneAndDrawsNoPrimaries) {
    FrameSettings none;
    none.primaries = false;
    none.mean_filter = 0;
    RendererState volumes;
    volumes.cut_volumes = true;
    const FramePlan plan = plan_frame(none, volumes);
    EXPECT_EQ(passes_of(plan, "cut_surface"), (std::vector<FramePass>{FramePass::clear_cut, FramePass::volume_cut,
                                                                     FramePass::rear_shell, FramePass::resolve_cut}));
    EXPECT_FALSE(plan.runs(FramePass::primaries));
    EXPECT_TRUE(plan.runs(FramePass::secondaries));
    // Distributed with a cone-field strategy: no strategy runs, so the cut itself is combined.
    volumes.distributed = volumes.cone_field_strategy = true;
    const FramePlan ranks = plan_frame(none, volumes);
    EXPECT_FALSE(ranks.combine_seeds);
    EXPECT_TRUE(ranks.combine_cut_depth);
    EXPECT_EQ(first_unwritten_read(ranks), "");
}

TEST(FramePlan, ThePapersPathListsSecondaryFacesUntimed) {
    FrameSettings s;
    s.draw = DrawMode::all_faces;
    const FramePlan plan = plan_frame(s, RendererState{});
    EXPECT_FALSE(plan.runs(FramePass::culling));
    EXPECT_EQ(passes_of(plan, ""), std::vector<FramePass>{FramePass::secondary_list});
}

TEST(FramePlan, EverySettingCombinationIsConsistent) {
    // Every combination of the switches that change the plan: no pass reads an unwritten target.
    for (int bits = 0; bits < 1 << 13; ++bits) {
        FrameSettings s;
        s.see_through = bits & 1;
        s.mean_filter = (bits & 2) ? 9 : 0;
        s.only = (bits & 4) ? OnlyLayer::secondaries : ((bits & 8) ? OnlyLayer::primaries : OnlyLayer::both);
        s.draw = (bits & 16) ? DrawMode::all_faces : DrawMode::visible;
        s.cut_enabled = !(bits & 32);
        RendererState state;
        state.frozen = bits & 64;
        state.frozen_cut_valid = (bits & 64) && (bits & 128);
        state.distributed = bits & 256;
        state.cone_field_strategy = bits & 512;
        state.cut_volumes = bits & 1024;
        s.primaries = !(bits & 2048);
        state.wells = bits & 4096;
        const FramePlan plan = plan_frame(s, state);
        EXPECT_EQ(first_unwritten_read(plan), "") << "combination " << bits;
    }
}

TEST(FramePlan, WellsAreDrawnAfterThePrimariesAndLabelledAfterTheColourBar) {
    EXPECT_FALSE(plan_frame(FrameSettings{}, RendererState{}).runs(FramePass::wells));
    RendererState state;
    state.wells = true;
    const FramePlan plan = plan_frame(FrameSettings{}, state);
    EXPECT_EQ(passes_of(plan, "primary"), (std::vector<FramePass>{FramePass::bind_scene, FramePass::primaries, FramePass::wells,
                                                                   FramePass::shell_contours, FramePass::reset_depth_test}));
    EXPECT_EQ(passes_of(plan, "post"),
              (std::vector<FramePass>{FramePass::composite, FramePass::colour_bar, FramePass::well_labels}));
    // Wells are a layer of their own: drawn without primaries too.
    FrameSettings only_secondaries;
    only_secondaries.only = OnlyLayer::secondaries;
    EXPECT_TRUE(plan_frame(only_secondaries, state).runs(FramePass::wells));
    // Distributed: every rank draws the tubes (depth-composited); only the display rank labels.
    state.distributed = true;
    state.screen_passes = false;
    const FramePlan rank = plan_frame(FrameSettings{}, state);
    EXPECT_TRUE(rank.runs(FramePass::wells));
    EXPECT_FALSE(rank.runs(FramePass::well_labels));
    EXPECT_EQ(first_unwritten_read(rank), "");
}

TEST(FramePlan, AnUnwrittenReadIsFound) {
    // The check itself can fail: a plan whose stage 2 reads a cut no pass made.
    FramePlan broken = plan_frame(FrameSettings{}, RendererState{});
    broken.stages.erase(broken.stages.begin(), broken.stages.begin() + 2);
    EXPECT_NE(first_unwritten_read(broken), "");
}

}  // namespace
}  // namespace cutaway::pipeline
