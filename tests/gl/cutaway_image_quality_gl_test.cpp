// What a reader of a figure sees (issue 15's image checks that concern the renderer itself):
// the model is never see-through by default. The cut stops just in front of the farthest shell
// (or fault) surface along each ray, so the rear shows as cut fill where the paper's frustums
// would leave the model through its rear shell and show the background; and the cut walls read
// as the cells' colours, not as a black mesh of lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <optional>
#include <random>

#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

constexpr int width = 320, height = 240;

/// Share of the uncut model's silhouette that shows background in the cutaway frame (its cut made
/// from `frozen`, freeze view, when given).
double background_in_silhouette(pipeline::CutawayRenderer& renderer, pipeline::FrameSettings settings,
                                const pipeline::Camera& camera, const std::optional<pipeline::Camera>& frozen = {}) {
    if (frozen) renderer.freeze(*frozen);
    renderer.render(settings, camera);
    const std::vector<std::uint32_t> cut = pipeline::FrameReadback(renderer).read_eclipse_ids();
    renderer.freeze(std::nullopt);
    settings.cut_enabled = false;
    renderer.render(settings, camera);
    const std::vector<std::uint32_t> uncut = pipeline::FrameReadback(renderer).read_eclipse_ids();
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
        renderer->select(random_primaries(grid, random));
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

// --only secondaries: the cutaway with the primaries taken out. The rear-shell clamp used to be
// lifted wherever a primary covered a pixel (the primary hid the background there); with the
// primaries hidden the cut then ran through the whole model behind each of them and the figure
// showed 15-17% of the silhouette as background (issue 46). Where a hidden primary is itself the
// model's rear shell no secondary lies behind it: its far walls are drawn (grey cut fill), or
// the background showed there (1.3-1.8% of fig. 15's panels). Primaries inside the shell (an IJK
// box) and anywhere, touching the rear shell from both sides.
TEST(CutawayImageQuality, OnlySecondariesKeepTheSilhouetteWherePrimariesWere) {
    auto renderer = make_renderer(petra(), width, height);
    const grid::GridDims& d = petra().dims();
    const grid::IjkBox inside{2, 2, 1, d.nx - 3, d.ny - 3, d.nz - 2};
    const grid::PrimaryRange range = grid::range_for_fraction(petra(), *petra().property("PORO"), "PORO", 0.05);
    double worst = 0;
    std::size_t walls = 0;
    for (const bool boxed : {true, false}) {
        if (boxed) renderer->select({range, inside});
        else renderer->select({range});
        for (const float azimuth : {35.0f, 215.0f}) {
            const pipeline::Camera camera =
                pipeline::make_orbit_camera(renderer->frame(), {azimuth, 30, 0, glm::vec3(0)}, width, height);
            pipeline::FrameSettings settings;
            settings.ssao = false;  // speed; the cut does not depend on it
            settings.only = pipeline::OnlyLayer::secondaries;
            const double share = background_in_silhouette(*renderer, settings, camera);
            std::cout << "  only secondaries, " << (boxed ? "primaries off the shell" : "primaries anywhere") << ", azimuth "
                      << azimuth << ": background inside the silhouette " << 100 * share << "%\n";
            worst = std::max(worst, share);
            // No primary pixel is drawn; the walls of the hidden ones show as cut fill.
            renderer->render(settings, camera);  // background_in_silhouette drew the uncut frame last
            const pipeline::IdImage ids = pipeline::RendererProbe(*renderer).read_ids();
            for (const std::uint32_t flags : ids.flags) {
                EXPECT_EQ(flags & pipeline::flag_primary, 0u);
                walls += (flags & pipeline::flag_cut_fill) != 0;
            }
        }
    }
    EXPECT_LT(worst, 0.005);  // issue 46's bound for every figure panel, as the full frame's above
    EXPECT_GT(walls, 0u);
}

// Freeze view: the cut is made from one camera, then the model camera moves (paper figure 10:
// azimuth 35 frozen, turned to 80). The frozen cut's own rear-shell clamp follows the frozen
// camera's rays, so from the moved camera the rear shell must be kept as well (the model
// camera's, shaders/common/cut_lookup.glsl); without it figure 10's frozen panel showed the
// background through the cut.
TEST(CutawayImageQuality, FrozenViewFromAMovedCameraIsNotSeeThrough) {
    auto renderer = make_renderer(petra(), width, height);
    renderer->select(grid::range_for_fraction(petra(), *petra().property("PORO"), "PORO", 0.01));
    const auto camera_at = [&](float azimuth, float elevation) {
        return pipeline::make_orbit_camera(renderer->frame(), {azimuth, elevation, 0, glm::vec3(0)}, width, height);
    };
    const pipeline::Camera frozen = camera_at(35, 30);
    struct Move {
        float azimuth, elevation;
        bool aperture_180;
        pipeline::DrawMode draw;
    };
    // Figure 10's turn, larger turns either way and upwards, aperture 180, both stage-2 face sources.
    const Move moves[] = {{80, 30, false, pipeline::DrawMode::visible},   {80, 30, false, pipeline::DrawMode::all_faces},
                          {-20, 30, false, pipeline::DrawMode::visible},  {125, 40, false, pipeline::DrawMode::visible},
                          {35, 70, false, pipeline::DrawMode::visible},   {80, 30, true, pipeline::DrawMode::visible}};
    double worst = 0, worst_raw = 0;
    for (const Move& move : moves) {
        pipeline::FrameSettings settings;
        settings.ssao = false;  // speed; the cut does not depend on it
        settings.draw = move.draw;
        if (move.aperture_180) pipeline::set_aperture_180(settings);
        const pipeline::Camera camera = camera_at(move.azimuth, move.elevation);
        const double share = background_in_silhouette(*renderer, settings, camera, frozen);
        settings.see_through = true;
        const double raw = background_in_silhouette(*renderer, settings, camera, frozen);
        std::cout << "  frozen at azimuth 35, seen from " << move.azimuth << "/" << move.elevation
                  << (move.aperture_180 ? " (aperture 180)" : "") << ": background " << 100 * share
                  << "% of the silhouette (see-through: " << 100 * raw << "%)\n";
        worst = std::max(worst, share);
        worst_raw = std::max(worst_raw, raw);
    }
    // 0.5%: issue 15's bound for figures, as for the unfrozen frames above (what may remain: pixels
    // on the silhouette's edge that the rear shell and the front faces rasterise differently).
    EXPECT_LT(worst, 0.005);
    // The raw frozen cut does open these views to the background, so the check above can fail.
    EXPECT_GT(worst_raw, 0.05);
}

/// Luminance (0..255, Rec. 709) of the final frame at id-image pixel i (ids: rows bottom to top,
/// the image: top to bottom).
double luminance(const gl::RgbaImage& image, std::size_t i) {
    const std::size_t x = i % std::size_t(image.width), y = std::size_t(image.height) - 1 - i / std::size_t(image.width);
    const std::uint8_t* p = image.pixels.data() + 4 * (y * std::size_t(image.width) + x);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
    return values[values.size() / 2];
}

struct FillLuminance {
    double median = 0;        ///< of the pixels (0..255)
    double near_black = 0;    ///< share below 40/255
    std::size_t line_pixels = 0;  ///< cell edge or border-line pixels (shell-cut lines excluded)
};

/// Luminance of the cut-fill pixels of the frame (`cut_fill`), or of every model pixel.
FillLuminance fill_luminance(pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings,
                             const pipeline::Camera& camera, bool cut_fill) {
    renderer.render(settings, camera);
    const pipeline::IdImage ids = pipeline::RendererProbe(renderer).read_ids();
    const gl::RgbaImage image = pipeline::FrameReadback(renderer).read_image();
    std::vector<double> values;
    std::size_t lines = 0;
    for (std::size_t i = 0; i < ids.cell.size(); ++i) {
        const std::uint32_t f = ids.flags[i];
        if (ids.cell[i] == 0 || (cut_fill && !(f & pipeline::flag_cut_fill))) continue;
        values.push_back(luminance(image, i));
        lines += (f & (pipeline::flag_edge | pipeline::flag_border)) && !(f & pipeline::flag_shell_cut);
    }
    const auto dark = std::count_if(values.begin(), values.end(), [](double l) { return l < 40.0; });
    return {median(values), values.empty() ? 0.0 : double(dark) / double(values.size()), lines};
}

TEST(CutawayImageQuality, CutWallsShowTheirColoursNotBlackLines) {
    // Petra at 800 x 600: its cells are 5-15 pixels across, as a figure's cells are at 1080p.
    constexpr int w = 800, h = 600;
    auto renderer = make_renderer(petra(), w, h);
    const std::vector<float>& poro = *petra().property("PORO");
    renderer->select(grid::range_for_fraction(petra(), poro, "PORO", 0.01));
    std::mt19937 random(3);
    for (int round = 0; round < 3; ++round) {
        const pipeline::OrbitPose pose{float(random() % 360), 25.0f + float(random() % 40), 0.0f, glm::vec3(0)};
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), pose, w, h);
        pipeline::FrameSettings settings;
        const FillLuminance fill = fill_luminance(*renderer, settings, camera, true);
        settings.hide_internal_lines = true;
        const FillLuminance hidden = fill_luminance(*renderer, settings, camera, true);
        settings.hide_internal_lines = false;
        settings.cut_enabled = false;
        const FillLuminance uncut = fill_luminance(*renderer, settings, camera, false);
        std::cout << "  cut fill: median luminance " << fill.median << " (uncut model " << uncut.median << "), near-black "
                  << 100 * fill.near_black << "% (" << 100 * hidden.near_black << "% with hidden lines), line pixels "
                  << fill.line_pixels << " (" << hidden.line_pixels << ")\n";
        // Issue 15's bounds: the fill at least 0.6 of the uncut surface's brightness (the cut fill
        // faces away from the headlight more often, and SSAO darkens its creases), and at most 15%
        // near-black pixels (what remains: the dark end of the colour map in shadow, creases).
        EXPECT_GE(fill.median, 0.6 * uncut.median);
        EXPECT_LT(fill.near_black, 0.15);
        // --hide-internal-lines removes every edge and border line from the cut fill (the lines
        // where the shell meets the cut stay); the frames do have such lines otherwise.
        EXPECT_GT(fill.line_pixels, 1000u);
        EXPECT_EQ(hidden.line_pixels, 0u);
    }
}

/// SSAO's shading of the cut fill: per pixel showing a cell's inside (no line on it or its right
/// neighbour), the luminance with SSAO over that without; returns the share of pixels on the fill
/// where that ratio changes by more than 0.1 to the right neighbour (a wall shaded smoothly: few).
double ssao_roughness_on_cut_fill(pipeline::CutawayRenderer& renderer, pipeline::FrameSettings settings,
                                  const pipeline::Camera& camera) {
    settings.ssao = false;
    renderer.render(settings, camera);
    const pipeline::IdImage ids = pipeline::RendererProbe(renderer).read_ids();
    const gl::RgbaImage plain = pipeline::FrameReadback(renderer).read_image();
    settings.ssao = true;
    renderer.render(settings, camera);
    const gl::RgbaImage shaded = pipeline::FrameReadback(renderer).read_image();
    const std::uint32_t lines = pipeline::flag_edge | pipeline::flag_border | pipeline::flag_shell_cut;
    auto fill = [&](std::size_t i) {
        return ids.cell[i] != 0 && (ids.flags[i] & pipeline::flag_cut_fill) && !(ids.flags[i] & lines) &&
               luminance(plain, i) > 10.0;
    };
    std::size_t steps = 0, pairs = 0;
    for (std::size_t i = 0; i + 1 < ids.cell.size(); ++i) {
        if ((i + 1) % std::size_t(ids.width) == 0 || !fill(i) || !fill(i + 1)) continue;
        steps += std::abs(luminance(shaded, i) / luminance(plain, i) - luminance(shaded, i + 1) / luminance(plain, i + 1)) > 0.1;
        ++pairs;
    }
    return pairs ? double(steps) / double(pairs) : 0.0;
}

TEST(CutawayImageQuality, SsaoSeesTheCutFillAsTheCutSurface) {
    // Fig. 11's frame: an aperture-180 cut through petra's thin layers, primaries SWAT 0.5-1 at
    // the generator's step 0. The cut fill's stored depths are the cells' far faces, a sawtooth
    // behind the wall; SSAO read them and darkened the wall into a lattice. Reading the cut's
    // depth there, SSAO shades the wall as one surface.
    constexpr int w = 1280, h = 720;
    auto renderer = make_renderer(petra(), w, h);
    renderer->select(grid::select_primaries(petra(), *petra().dynamic_property("SWAT", 0), "SWAT", {0.5f, 1.0f}));
    for (const float azimuth : {35.0f, 215.0f}) {
        const pipeline::OrbitPose pose{azimuth, 30.0f, 0.0f, glm::vec3(0)};
        pipeline::FrameSettings settings;
        pipeline::set_aperture_180(settings);
        const double roughness =
            ssao_roughness_on_cut_fill(*renderer, settings, pipeline::make_orbit_camera(renderer->frame(), pose, w, h));
        std::cout << "  azimuth " << azimuth << ": SSAO's change from a cut-fill pixel to the next " << roughness << "\n";
        // Measured: 1.1% and 0.8% of the fill's pixels; with the far faces' depths (before the
        // fix) 2.2% and 1.6%, the lattice's edges. What remains: the wall's foot and the creases
        // where the fill meets other cells' faces, and SSAO's per-pixel sample rotation.
        EXPECT_LT(roughness, 0.015);
    }
}

}  // namespace
}  // namespace cutaway::test
