// What a reader of a figure sees (issue 15's image checks that concern the renderer itself):
// the model is never see-through by default. The cut stops just in front of the farthest shell
// (or fault) surface along each ray, so the rear shows as cut fill where the paper's frustums
// would leave the model through its rear shell and show the background.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "gl_test_support.h"

namespace cutaway::test {
namespace {

constexpr int width = 320, height = 240;

/// Share of the uncut model's silhouette that shows background in the cutaway frame.
double background_in_silhouette(pipeline::CutawayRenderer& renderer, pipeline::FrameSettings settings,
                                const pipeline::Camera& camera) {
    renderer.render(settings, camera);
    const std::vector<std::uint32_t> cut = renderer.read_eclipse_ids();
    settings.cut_enabled = false;
    renderer.render(settings, camera);
    const std::vector<std::uint32_t> uncut = renderer.read_eclipse_ids();
    std::size_t silhouette = 0, holes = 0;
    for (std::size_t i = 0; i < cut.size(); ++i) {
        if (uncut[i] == 0) continue;
        ++silhouette;
        if (cut[i] == 0) ++holes;
    }
    return silhouette ? double(holes) / double(silhouette) : 0.0;
}

/// Worst see-through share over random poses and selections, clamped and raw.
void check_no_see_through(const grid::CornerPointGrid& grid, unsigned seed) {
    auto renderer = make_renderer(grid, width, height);
    std::mt19937 random(seed);
    double worst_clamped = 0, worst_raw = 0;
    for (int round = 0; round < 8; ++round) {
        renderer->set_primaries(random_primaries(grid, random));
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), random_pose(random), width, height);
        pipeline::FrameSettings settings;
        settings.ssao = false;  // speed; the cut does not depend on it
        if (round % 2 == 1) pipeline::set_aperture_180(settings);
        worst_clamped = std::max(worst_clamped, background_in_silhouette(*renderer, settings, camera));
        settings.see_through = true;
        worst_raw = std::max(worst_raw, background_in_silhouette(*renderer, settings, camera));
    }
    std::cout << "  background inside the silhouette: worst " << 100 * worst_clamped << "% (see-through: "
              << 100 * worst_raw << "%)\n";
    // 0.5%: issue 15's bound for figures; what remains are silhouette-edge pixels where the rear
    // shell and the front faces rasterise to different pixel sets (measured: 0 on these frames).
    EXPECT_LT(worst_clamped, 0.005);
    // The raw cut does leave the model on these frames (aperture 180 removes everything in front
    // of the primaries' backs), so the check above can fail.
    EXPECT_GT(worst_raw, 0.05);
}

TEST(CutawayImageQuality, PetraIsNotSeeThrough) { check_no_see_through(petra(), 1); }

TEST(CutawayImageQuality, FaultedModelWithInactiveCellsIsNotSeeThrough) {
    check_no_see_through(faulted_model_with_inactive_cells({24, 20, 8}, 0.25, 7), 2);
}

}  // namespace
}  // namespace cutaway::test
