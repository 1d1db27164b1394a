// The mean filter (src/cutaway/post/mean_filter.h) against a CPU box filter on random depth
// images, and the distance-scaled kernel against the full kernel on rendered frames: the same
// wherever the radius stays the full one, nearer the unfiltered cut where it shrinks (the far cut
// walls), and no primary pixel lost.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "cutaway/cut_surface/cut_depth_image.h"
#include "cutaway/post/mean_filter.h"
#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"
#include "metrics/image_metrics.h"

namespace cutaway::test {
namespace {

constexpr int width = 400, height = 300;
constexpr int kernel = 9, full_radius = kernel / 2;  // the paper's 9x9

/// The cut of one frame (depth along the cut camera's axis, rows bottom to top, 0 = nothing cut)
/// and its ids.
struct Frame {
    std::vector<float> cut;
    pipeline::IdImage ids;
};

Frame render(pipeline::CutawayRenderer& renderer, pipeline::FrameSettings settings, const pipeline::Camera& camera,
             int mean_filter, pipeline::MeanFilterKernel kernel_kind) {
    settings.mean_filter = mean_filter;
    settings.mean_filter_kernel = kernel_kind;
    renderer.render(settings, camera);
    return {pipeline::RendererProbe(renderer).read_cut_depth().values, pipeline::RendererProbe(renderer).read_ids()};
}

/// The k x k mean with edges clamped, every `stride`-th texel along each axis from -k/2 (double).
cone_field::FloatImage box_mean(const cone_field::FloatImage& image, int size, int stride) {
    cone_field::FloatImage out(image.width, image.height);
    const int r = size / 2;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            double sum = 0;
            int count = 0;
            for (int dy = -r; dy <= r; dy += stride)
                for (int dx = -r; dx <= r; dx += stride) {
                    sum += image.at(std::clamp(x + dx, 0, image.width - 1), std::clamp(y + dy, 0, image.height - 1));
                    ++count;
                }
            out.at(x, y) = float(sum / count);
        }
    return out;
}

void check_box_mean(int image_width) {
    // Odd sizes (edges clamped on every side), a quarter of the pixels with nothing cut (0, which
    // the filter averages like any depth). The camera has near = 0, so stored depth s / far is
    // linear in s and the stored mean is the mean of the depths. Tolerance: the GPU sums k floats
    // per pass in float, the CPU in double: k + 2 roundings of values <= 1 (2^-24 each) per pass,
    // times far for depth units.
    pipeline::Camera camera;
    camera.width = image_width;
    camera.height = 61;
    camera.near_plane = 0.0f;
    camera.far_plane = 100.0f;
    std::mt19937 random(5);
    std::uniform_real_distribution<float> depth(1.0f, 99.0f);
    std::uniform_int_distribution<int> quarter(0, 3);
    cone_field::FloatImage cut(camera.width, camera.height);
    for (float& s : cut.pixels) s = quarter(random) == 0 ? 0.0f : depth(random);
    const pipeline::CutTargets input(camera.width, camera.height), output(camera.width, camera.height);
    pipeline::write_cut_depth_texture(cut, camera, input.depth);
    pipeline::MeanFilter filter(GlEnvironment::shaders());
    struct Case {
        int size;
        pipeline::MeanFilterKernel kernel;
        float reference_depth;  // distance-scaled: beyond every depth = the full kernel; below them = radius 1
        int expected_size, stride;
    };
    for (const Case& c : {Case{9, pipeline::MeanFilterKernel::full, 0, 9, 1}, Case{3, pipeline::MeanFilterKernel::full, 0, 3, 1},
                          Case{33, pipeline::MeanFilterKernel::full, 0, 33, 1}, Case{9, pipeline::MeanFilterKernel::sampled, 0, 9, 2},
                          Case{9, pipeline::MeanFilterKernel::distance_scaled, 1000.0f, 9, 1}}) {
        SCOPED_TRACE("kernel " + std::to_string(c.size) + " kind " + std::to_string(int(c.kernel)));
        filter.apply(input, output, c.size, c.kernel, camera, c.reference_depth);
        const cone_field::FloatImage gpu = pipeline::read_cut_depth_texture(output.depth, camera);
        const cone_field::FloatImage cpu = box_mean(cut, c.expected_size, c.stride);
        const double tolerance = 2.0 * (c.expected_size + 2) * std::ldexp(1.0, -24) * camera.far_plane;
        double largest = 0;
        for (std::size_t i = 0; i < cut.pixel_count(); ++i) largest = std::max(largest, double(std::abs(gpu.pixels[i] - cpu.pixels[i])));
        EXPECT_LE(largest, tolerance);
    }
}

TEST(MeanFilter, EqualsTheBoxMeanOnRandomDepthImages) { check_box_mean(97); }
// A width of whole 4-pixel texels: the full kernel takes 4 pixels per invocation (QUADS).
TEST(MeanFilter, EqualsTheBoxMeanFourPixelsAtATime) { check_box_mean(96); }

TEST(MeanFilterKernel, DistanceScaledIsTheFullKernelNearAndSharperOnFarWalls) {
    auto renderer = make_renderer(petra(), width, height);
    renderer->select(grid::range_for_fraction(petra(), *petra().property("PORO"), "PORO", 0.01));
    for (const float azimuth : {125.0f, 215.0f}) {
        SCOPED_TRACE("azimuth " + std::to_string(azimuth));
        const pipeline::Camera camera =
            pipeline::make_orbit_camera(renderer->frame(), {azimuth, 20, 0, glm::vec3(0)}, width, height);
        pipeline::FrameSettings settings;
        settings.ssao = false;  // speed; the cut does not depend on it
        const Frame raw = render(*renderer, settings, camera, 0, pipeline::MeanFilterKernel::full);
        // The strategy's cut before the resolve's rear-shell clamp: what sets the shader's radius.
        const cone_field::FloatImage strategy = pipeline::RendererProbe(*renderer).read_strategy_cut(camera);  // rows top to bottom
        const Frame full = render(*renderer, settings, camera, kernel, pipeline::MeanFilterKernel::full);
        const Frame scaled = render(*renderer, settings, camera, kernel, pipeline::MeanFilterKernel::distance_scaled);
        settings.only = pipeline::OnlyLayer::primaries;
        const Frame primaries = render(*renderer, settings, camera, 0, pipeline::MeanFilterKernel::full);

        const float reference = pipeline::mean_filter_reference_depth(renderer->frame(), camera);
        const auto strategy_depth = [&](int x, int y) {
            return strategy.at(std::clamp(x, 0, width - 1), height - 1 - std::clamp(y, 0, height - 1));
        };
        // The shader's radius at (x, y), decided well away from rounding ties: R where the cut is
        // nearer than the reference depth (or absent), -1 where it is undecided here.
        const auto radius = [&](int x, int y) {
            const float s = strategy_depth(x, y);
            if (s <= 0 || s < 0.999f * reference) return full_radius;
            const float exact = float(full_radius) * reference / s;
            if (std::abs(exact - std::floor(exact) - 0.5f) < 0.01f) return -1;
            return std::clamp(int(std::lround(exact)), 1, full_radius);
        };
        std::size_t same_pixels = 0, far_pixels = 0;
        double worst_same = 0, full_error = 0, scaled_error = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = std::size_t(y) * width + std::size_t(x);
                if (raw.cut[i] <= 0) continue;
                // Full radius over the whole window: both passes average the same texels.
                bool window_full = true;
                for (int dy = -full_radius; dy <= full_radius && window_full; ++dy)
                    for (int dx = -full_radius; dx <= full_radius && window_full; ++dx)
                        window_full = radius(x + dx, y + dy) == full_radius;
                if (window_full) {
                    ++same_pixels;
                    worst_same = std::max(worst_same, double(std::abs(scaled.cut[i] - full.cut[i]) / full.cut[i]));
                } else if (radius(x, y) >= 1 && radius(x, y) < full_radius) {
                    ++far_pixels;
                    full_error += std::abs(full.cut[i] - raw.cut[i]);
                    scaled_error += std::abs(scaled.cut[i] - raw.cut[i]);
                }
            }
        const metrics::Exposure exposure = metrics::primary_exposure(
            {primaries.ids.width, primaries.ids.height, primaries.ids.cell, primaries.ids.flags},
            {scaled.ids.width, scaled.ids.height, scaled.ids.cell, scaled.ids.flags});
        std::cout << "  azimuth " << azimuth << ": reference depth " << reference << ", " << same_pixels
                  << " cut pixels at the full radius (worst relative difference " << worst_same << "), " << far_pixels
                  << " with a smaller one: mean distance to the unfiltered cut " << scaled_error / double(far_pixels)
                  << " (full kernel " << full_error / double(far_pixels) << "), primary exposure " << exposure.fraction
                  << "\n";
        // Both frames are made on the GPU by the same sums in the same order there: equal but for
        // the last bit (1e-6 relative, a few float ulps).
        EXPECT_GT(same_pixels, 1000u);
        EXPECT_LT(worst_same, 1e-6);
        // Where the radius shrinks, the cut stays nearer the strategy's: the far walls keep
        // their shape. Each frame has such pixels (the cut behind the model's centre).
        EXPECT_GT(far_pixels, 1000u);
        EXPECT_LT(scaled_error, 0.8 * full_error);
        // The smaller window does not lift the cut onto a primary: every primary pixel stays visible.
        EXPECT_GT(exposure.primary_pixels, 0u);
        EXPECT_EQ(exposure.fraction, 1.0);
    }
}

}  // namespace
}  // namespace cutaway::test
