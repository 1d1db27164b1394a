// frustum-sweep (O(pixels), chessboard sweeps over the box back faces) against the rasterised
// frustum union with every wall at the same pixel slope m, pixel by pixel, on petra with random
// selections, poses and apertures. Where that holds the sweep is the exact union up to the
// seeds' pixel sampling: never above the raster, at most m (one pixel's depth step) below it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cutaway/cut_surface/cell_boxes.h"
#include "cutaway/cut_surface/cone_field_strategy.h"
#include "cutaway/cut_surface/cut_depth_image.h"
#include "cutaway/renderer_readback.h"
#include "gl/uniforms.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

constexpr int width = 320, height = 240;

TEST(FrustumSweep, EqualsTheRasterisedUnionOfEqualSlopeFrustumsWithinAPixelStep) {
    auto renderer = make_renderer(petra(), width, height);
    const gl::Program raster = pipeline::build_cell_box_program(GlEnvironment::shaders(), {.constant_wall_slope = true});
    const pipeline::CutTargets targets(width, height);
    const gl::VertexArray no_attributes;
    std::mt19937 random(17);
    for (int trial = 0; trial < 4; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        renderer->select(random_primaries(petra(), random));
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), random_pose(random), width, height);
        pipeline::FrameSettings settings = invariant_settings(random);
        settings.aperture_h_deg = std::max(settings.aperture_h_deg, 10.0f);  // a slope below 1e4 per pixel
        settings.strategy = "frustum-sweep";
        renderer->render(settings, camera);
        const cone_field::FloatImage sweep = pipeline::RendererProbe(*renderer).read_strategy_cut(camera);

        const pipeline::CutSurfaceInputs inputs = pipeline::RendererProbe(*renderer).cut_inputs(settings, camera);
        const double m = pipeline::cut_cone_slope(inputs);  // depth units per pixel
        gl::set_uniform(raster, "wall_u_per_depth", float(1.0 / (m * camera.focal_px())));
        targets.clear();
        no_attributes.bind();
        pipeline::draw_cell_boxes(raster, inputs, targets.framebuffer);
        const cone_field::FloatImage union_depth = pipeline::read_cut_depth_texture(targets.depth, camera);

        // Both sides store depths in [0, 1] of the range (1e-7 of it each) and the sweeps round
        // once per step along paths of at most W + H steps (gpu_chamfer.cpp).
        const double rounding = (width + height + 8) * std::ldexp(1.0, -24) * (camera.far_plane - camera.near_plane);
        std::size_t inside_rim = 0;
        for (std::size_t i = 0; i < sweep.pixels.size(); ++i) {
            const double r = union_depth.pixels[i], s = sweep.pixels[i];
            if (r > 0) {  // inside the walls, which stop at the rim
                ++inside_rim;
                ASSERT_LE(s, r + rounding) << "pixel " << i;
                ASSERT_GE(s, r - m - rounding) << "pixel " << i;
            } else {  // outside every frustum down to the rim: the sweep holds nothing deeper than the rim
                ASSERT_LE(s, double(inputs.rim_depth) + m + rounding) << "pixel " << i;
            }
        }
        EXPECT_GT(inside_rim, sweep.pixels.size() / 10) << "too little cut to compare";
        RecordProperty("pixels_compared_trial_" + std::to_string(trial), int(inside_rim));
    }
}

}  // namespace
}  // namespace cutaway::test
