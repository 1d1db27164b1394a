// Cells that open their cut over frames (smooth coherence, issue 44): at opening 1 a cell's cut is
// its frustum, the frustum union's cut of that cell as the only primary, pixel for pixel; at 0 it
// cuts nothing; in between the cut grows with the opening. Mean filter off for the exact
// comparison (it lowers the cut's edges, so a secondary cell shows where its own cut is filtered
// below it); with it on, the two frames differ only where the opening cell itself shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "cutaway/cutaway_renderer.h"
#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"
#include "metrics/temporal_metrics.h"

namespace cutaway::test {
namespace {

std::size_t cut_away_pixels(pipeline::CutawayRenderer& renderer) {
    const pipeline::IdImage ids = pipeline::FrameReadback(renderer).read_ids();
    const std::vector<metrics::CutState> states = metrics::cut_states(ids.cell, ids.flags);
    return std::size_t(std::count(states.begin(), states.end(), metrics::CutState::cut_away));
}

/// Strategy name; whether its cut of one primary is exactly the cell's opening cut at 1.
struct OpeningCase {
    const char* strategy;
    bool exact;
};

class OpeningCutGl : public ::testing::TestWithParam<OpeningCase> {};

// frustum: the opening pass draws the same frustum. frustum-sweep (a seed strategy, llvmpipe's
// auto pick at these sizes): the opening cells are seeds beside the primaries', the same back
// face, but the cone slope is taken at the primaries' centroid, which moves when the cell joins
// them (here from none to the cell), so the full opening is checked for growth, not identity.
INSTANTIATE_TEST_SUITE_P(Strategies, OpeningCutGl, ::testing::Values(OpeningCase{"frustum", true}, OpeningCase{"frustum-sweep", false}),
                         [](const auto& info) { return std::string(info.param.exact ? "exact_" : "seeds_") + (info.index ? "sweep" : "frustum"); });

TEST_P(OpeningCutGl, FullOpeningIsTheCellsCutNoneCutsNothingAndTheCutGrowsBetween) {
    const grid::CornerPointGrid& grid = petra();
    constexpr int width = 320, height = 240;
    const auto renderer = make_renderer(grid, width, height);
    std::mt19937 random(44);
    pipeline::FrameSettings settings;
    settings.strategy = GetParam().strategy;
    settings.ssao = false;
    settings.colour_bar = false;
    settings.mean_filter = 0;
    // Only the secondaries: the frame with the cell as a primary and the frame with its opening
    // then differ only where their cuts do (the primary itself is not drawn in either).
    settings.only = pipeline::OnlyLayer::secondaries;
    const grid::GridDims d = grid.dims();
    std::uniform_int_distribution<int> pick_i(d.nx / 4, 3 * d.nx / 4), pick_j(d.ny / 4, 3 * d.ny / 4);
    int checked = 0;
    for (int trial = 0; trial < 20 && checked < 4; ++trial) {
        // A cell in the middle of the model, deep enough that its cut crosses several layers.
        const std::size_t cell = std::size_t(pick_i(random)) + std::size_t(d.nx) * (std::size_t(pick_j(random)) + std::size_t(d.ny) * std::size_t(d.nz * 3 / 4));
        if (!grid.actnum()[cell]) continue;
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), random_pose(random), width, height, 0);
        std::vector<std::uint8_t> flags(grid.cell_count(), 0);
        flags[cell] = 1;
        renderer->set_opening_cells({});
        renderer->select(flags);
        renderer->render(settings, camera);
        const std::vector<std::uint32_t> as_primary = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        const std::size_t primary_cut = cut_away_pixels(*renderer);
        if (primary_cut == 0) continue;  // the cell is on the model's near side: its frustum cuts nothing
        ++checked;

        renderer->select(pipeline::Primaries::none());
        renderer->set_opening_cells({});
        renderer->render(settings, camera);
        const std::vector<std::uint32_t> without = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        // A few pixels may show a cell's inside without any cut (where the model's own faces leave
        // a gap): the uncut frame's count is the floor.
        const std::size_t cut_away_pixels_without = cut_away_pixels(*renderer);
        std::size_t previous = cut_away_pixels_without;
        for (float opening : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
            renderer->set_opening_cells({{std::uint32_t(cell), opening}});
            renderer->render(settings, camera);
            const std::size_t cut = cut_away_pixels(*renderer);
            if (opening == 0.0f) {
                EXPECT_EQ(pipeline::FrameReadback(*renderer).read_eclipse_ids(), without) << "trial " << trial;
            }
            EXPECT_GE(cut, previous) << "trial " << trial << " opening " << opening;
            previous = cut;
        }
        EXPECT_GT(previous, cut_away_pixels_without) << "trial " << trial;
        // The seed strategies draw the openings among their seeds, the others in a pass of their own.
        EXPECT_EQ(renderer->status(settings).last_plan.runs(pipeline::FramePass::opening_cut), GetParam().exact);
        if (!GetParam().exact) continue;
        // The same frustum drawn by the same shaders with opening 1: identical ids, not a tolerance.
        EXPECT_EQ(pipeline::FrameReadback(*renderer).read_eclipse_ids(), as_primary) << "trial " << trial;
        EXPECT_EQ(previous, primary_cut) << "trial " << trial;

        pipeline::FrameSettings filtered = settings;
        filtered.mean_filter = pipeline::FrameSettings{}.mean_filter;
        renderer->render(filtered, camera);
        const std::vector<std::uint32_t> opened = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        renderer->set_opening_cells({});
        renderer->select(flags);
        renderer->render(filtered, camera);
        const std::vector<std::uint32_t> primary = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        for (std::size_t p = 0; p < opened.size(); ++p) {
            if (opened[p] != primary[p]) {
                ASSERT_EQ(opened[p], cell + 1) << "trial " << trial << " pixel " << p;
            }
        }
    }
    EXPECT_EQ(checked, 4);
    EXPECT_THROW(renderer->set_opening_cells({{std::uint32_t(grid.cell_count()), 1.0f}}), std::invalid_argument);
}

}  // namespace
}  // namespace cutaway::test
