// Every cut-surface strategy of the registry against the SPEC section 2 invariants on EGL
// llvmpipe: each keeps every primary pixel visible with the mean filter off, and jump flooding
// stays within its error bounds against the exact cone field from the same seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <utility>

#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/cut_surface/cut_surface_registry.h"
#include "cutaway/frame_metrics.h"
#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"
#include "metrics/cut_error.h"

namespace cutaway::test {
namespace {

using pipeline::Camera;
using pipeline::make_orbit_camera;

TEST(CutStrategies, EveryStrategyKeepsEveryPrimaryPixelVisible) {
    // By construction for the cone fields: the seeds cover each primary's widened footprint at
    // its far depth plus the margin, and every cut is >= its seed at a seed pixel.
    constexpr int width = 320, height = 240;
    auto renderer = make_renderer(petra(), width, height);
    for (const pipeline::CutSurfaceEntry& entry : pipeline::cut_surface_strategies()) {
        SCOPED_TRACE("strategy " + entry.name);
        EXPECT_TRUE(entry.device == "gpu" || entry.device == "cpu") << entry.device;
        EXPECT_FALSE(entry.why.empty());
        std::mt19937 random(23);  // the same scenes for every strategy
        for (int trial = 0; trial < 3; ++trial) {
            SCOPED_TRACE("trial " + std::to_string(trial));
            renderer->select(random_primaries(petra(), random));
            const Camera camera = make_orbit_camera(renderer->frame(), random_pose(random), width, height);
            pipeline::FrameSettings settings = invariant_settings(random);
            settings.strategy = entry.name;
            // Both seed sources: boxes (back face widened by a pixel) and the cells' own faces.
            for (pipeline::SeedSource seeds : {pipeline::SeedSource::boxes, pipeline::SeedSource::geometry}) {
                if (seeds == pipeline::SeedSource::geometry && !entry.cpu_reference) continue;  // no seeds
                settings.seeds = seeds;
                SCOPED_TRACE(std::string("seeds ") + pipeline::to_string(seeds));
                const pipeline::FrameMetrics m = pipeline::measure_frame(*renderer, settings, camera);
                EXPECT_GT(m.exposure.primary_pixels, 0u);
                EXPECT_EQ(m.exposure.fraction, 1.0) << m.exposure.visible << " of " << m.exposure.primary_pixels;
                EXPECT_EQ(m.secondary_in_front, 0u);
            }
        }
    }
}

TEST(CutStrategies, JumpFloodingWithinItsErrorBoundsAgainstExactAt512) {
    // SPEC section 2's measured bounds, as they are: plain JFA at most 0.13% wrong pixels, JFA^2
    // at most 0.02%; errors one-sided (the cut is the height of a real seed's cone, never above
    // the exact maximum). A pixel is wrong when off by more than compare_cut's default tolerance
    // (1e-3 of the exact depth range). Here the transforms run on the GPU (float).
    constexpr int side = 512;
    const std::pair<const char*, double> bounds[] = {{"jfa", 0.0013}, {"jfa2", 0.0002}};
    auto renderer = make_renderer(petra(), side, side);
    std::mt19937 random(41);
    for (int trial = 0; trial < 3; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        renderer->select(random_primaries(petra(), random));
        const Camera camera = make_orbit_camera(renderer->frame(), random_pose(random), side, side);
        pipeline::FrameSettings settings = invariant_settings(random);
        const cone_field::FloatImage exact = pipeline::RendererProbe(*renderer).exact_cut(settings, camera);
        ASSERT_TRUE(std::any_of(exact.pixels.begin(), exact.pixels.end(), [](float d) { return d > 0; }))
            << "no cut at all: the comparison would be vacuous";
        for (const auto& [name, bound] : bounds) {
            SCOPED_TRACE(name);
            settings.strategy = name;
            renderer->render(settings, camera);
            const metrics::CutError error = metrics::compare_cut(pipeline::RendererProbe(*renderer).read_strategy_cut(camera), exact);
            EXPECT_LE(error.wrong_fraction, bound) << error.pixels_wrong << " of " << error.pixels_compared;
            EXPECT_LE(error.max_signed_error, error.tolerance);
            RecordProperty(std::string(name) + "_wrong_fraction_trial_" + std::to_string(trial), std::to_string(error.wrong_fraction));
        }
    }
}

TEST(CutStrategies, AutoDrawsClustersBelowTheDevicesThresholdAndTheSweepFromThere) {
    // "auto" (cut_strategy_choice.h) is no method of its own: its cut must be the chosen
    // strategy's, pixel for pixel, and differ from the other one's (else the check is vacuous).
    constexpr int width = 320, height = 240;
    auto renderer = make_renderer(petra(), width, height);
    const std::vector<float>& poro = *petra().property("PORO");
    std::mt19937 random(7);
    const Camera camera = make_orbit_camera(renderer->frame(), random_pose(random), width, height);
    pipeline::FrameSettings settings;
    settings.mean_filter = 0;
    const auto cut_of = [&](const std::string& strategy) {
        settings.strategy = strategy;
        renderer->render(settings, camera);
        return pipeline::RendererProbe(*renderer).read_strategy_cut(camera).pixels;
    };
    // Petra's 35,838 active cells: 1% of them lie below either threshold (500 on llvmpipe, 10,000 on a
    // GPU), half of them above both.
    const std::pair<double, std::string> cases[] = {{0.01, "frustum-clusters"}, {0.5, "frustum-sweep"}};
    for (const auto& [fraction, chosen] : cases) {
        SCOPED_TRACE("fraction " + std::to_string(fraction));
        renderer->select(grid::range_for_fraction(petra(), poro, "PORO", fraction));
        const auto automatic = cut_of(pipeline::auto_cut_strategy);
        const std::size_t primaries = renderer->status().primary_cells;
        EXPECT_EQ(primaries >= renderer->status().auto_sweep_from, chosen == "frustum-sweep") << primaries;
        EXPECT_EQ(renderer->status(settings).cut_strategy, chosen);
        const std::string other = chosen == "frustum-sweep" ? "frustum-clusters" : "frustum-sweep";
        EXPECT_NE(cut_of(other), automatic) << other << " draws the same cut: the test cannot tell them apart";
        EXPECT_EQ(cut_of(chosen), automatic);
    }
}

}  // namespace
}  // namespace cutaway::test
