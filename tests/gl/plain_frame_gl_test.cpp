// The plain frame (`render --baseline`, CutawayRenderer::render_baseline) has its own slim path:
// exposed faces chosen by the culling pass, a fragment shader without discard (early depth test)
// and colour + id + depth targets only. It must show what the full renderer shows when nothing is
// cut: the reference is a cutaway frame with no primary (no cut anywhere), drawn by stage 2's
// shader with every face of every cell. On random cameras the cell-id images must agree except
// at depth ties between coincident faces (a fault face is drawn once per cell beside it; the
// drawing order decides which cell wins): there both frames show a cell at the same window depth.
// One more kind of pixel may differ: the reference draws exposed faces seen from inside their own
// cell too, which a closed convex cell hides behind its front; the culling pass drops a face both
// of whose triangles face away, so where a warped cell's front leaves a sliver of its own back face
// visible the plain frame shows what lies behind it. Those pixels are named by the reference's
// flag for a face seen from inside its cell (flag_cut_fill, shaders/secondary/secondary.frag).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

using pipeline::DrawMode;

constexpr int width = 320, height = 240;
/// Window depths of coincident faces drawn by two paths: the same corners through the same
/// vertex shader, so equal up to interpolation rounding (24-bit-mantissa depth near 1).
constexpr float tie_window_depth = 1e-6f;
constexpr std::uint32_t flag_seen_from_inside = 2;  // flag_cut_fill of common/frame_outputs.glsl

void check_plain_frame(const grid::CornerPointGrid& grid, unsigned seed) {
    pipeline::CutawayRenderer renderer(GlEnvironment::shaders(), grid, 0.0, width, height);
    std::vector<float> values(grid.cell_count());
    for (std::size_t c = 0; c < values.size(); ++c) values[c] = float(c % 97);
    renderer.set_colouring(values, {"cell mod 97", 0, 96, ""});
    renderer.select(std::vector<std::uint8_t>(grid.cell_count(), 0));  // nothing cut
    std::mt19937 random(seed);
    std::size_t pixels = 0, model_pixels = 0, differing = 0, own_back_faces = 0, unexplained = 0;
    for (int trial = 0; trial < 8; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        pipeline::OrbitPose pose = random_pose(random);
        if (trial % 3 == 2) pose.distance = renderer.frame().radius() * 1.5f;  // part of the model outside
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer.frame(), pose, width, height);
        pipeline::FrameSettings settings;
        settings.draw = DrawMode::all_faces;
        settings.ssao = false;
        settings.mean_filter = 0;
        renderer.render(settings, camera);
        const std::vector<std::uint32_t> reference = pipeline::FrameReadback(renderer).read_eclipse_ids();
        const std::vector<std::uint32_t> reference_flags = pipeline::RendererProbe(renderer).read_ids().flags;
        const std::vector<float> reference_depth = pipeline::RendererProbe(renderer).read_window_depth();
        for (DrawMode draw : {DrawMode::visible, DrawMode::all_faces}) {
            renderer.render_baseline(camera, draw);
            const std::vector<std::uint32_t> plain = pipeline::FrameReadback(renderer).read_eclipse_ids();
            const std::vector<float> plain_depth = pipeline::RendererProbe(renderer).read_window_depth();
            for (std::size_t p = 0; p < plain.size(); ++p) {
                ++pixels;
                model_pixels += reference[p] != 0;
                if (plain[p] == reference[p]) continue;
                ++differing;
                if (plain[p] != 0 && reference[p] != 0 && std::abs(plain_depth[p] - reference_depth[p]) <= tie_window_depth)
                    continue;
                if ((reference_flags[p] & flag_seen_from_inside) != 0 && plain_depth[p] > reference_depth[p]) {
                    ++own_back_faces;
                    continue;
                }
                ++unexplained;
                if (unexplained <= 10)
                    std::cout << "  not a tie (" << pipeline::to_string(draw) << "): pixel " << p % width << "," << p / width << ": reference cell " << reference[p]
                              << " at " << reference_depth[p] << ", plain cell " << plain[p] << " at " << plain_depth[p] << "\n";
            }
        }
    }
    EXPECT_GT(model_pixels, pixels / 20) << "the model should cover part of the frames";
    EXPECT_LE(double(differing), 0.001 * double(pixels)) << differing << " of " << pixels << " pixels differ";
    EXPECT_EQ(unexplained, 0u);
    std::cout << "  plain frame: " << differing << " of " << pixels << " pixels differ: " << own_back_faces
              << " show a warped cell's own back face in the reference, " << differing - own_back_faces - unexplained
              << " depth ties, " << unexplained << " unexplained\n";
}

TEST(PlainFrame, PetraShowsWhatTheUncutRendererShows) { check_plain_frame(petra(), 11); }

TEST(PlainFrame, FaultedModelWithInactiveCellsShowsWhatTheUncutRendererShows) {
    check_plain_frame(faulted_model_with_inactive_cells({24, 20, 8}, 0.25, 5), 12);
}

}  // namespace
}  // namespace cutaway::test
