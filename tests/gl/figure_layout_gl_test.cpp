// What a figure's reader sees around the model (issue 15): the framed model fills the panel
// (its bounding box at least 85% of the panel's width or height), the colour bar draws only where
// its layout says and never over the model (nor under the viewer's panel or an animation's
// caption, when the camera keeps their columns or rows), and the silhouette has a colour of its own, apart
// from the red lines where the cut meets the shell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "annotation/colour_bar_layout.h"
#include "annotation/label_placement.h"
#include "cutaway/colour_map.h"
#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"
#include "metrics/median.h"

namespace cutaway::test {
namespace {

struct PixelBox {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // inclusive, image rows top to bottom
};

/// Bounds of the model's pixels (id image rows run bottom to top).
PixelBox model_pixels(const std::vector<std::uint32_t>& ids, int width, int height) {
    PixelBox box;
    for (int row = 0; row < height; ++row)
        for (int x = 0; x < width; ++x)
            if (ids[std::size_t(row) * std::size_t(width) + std::size_t(x)] != 0) {
                const int y = height - 1 - row;
                box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x), std::max(box.y1, y)};
            }
    return box;
}

const pipeline::OrbitPose poses[] = {
    {35, 30, 0, glm::vec3(0)}, {0, 10, 0, glm::vec3(0)}, {90, 60, 0, glm::vec3(0)},
    {200, 45, 0, glm::vec3(0)}, {300, 80, 0, glm::vec3(0)}, {135, 5, 0, glm::vec3(0)},
};

void check_framing(const grid::CornerPointGrid& grid, const char* name, int width, int height) {
    auto renderer = make_renderer(grid, width, height);
    const std::vector<float>& poro = *grid.property("PORO");
    renderer->select({grid::range_for_fraction(grid, poro, "PORO", 0.01)});
    pipeline::FrameSettings settings;
    settings.ssao = false;  // speed; framing does not depend on it
    const grid::PrimaryRange range = grid::active_value_range(grid, poro, "PORO");
    const annotation::ColourBarLayout bar = annotation::layout_colour_bar({"PORO", range.min, range.max, "frac"}, width, height);
    const annotation::PixelRect bounds = bar.bounds();
    for (const pipeline::OrbitPose& pose : poses) {
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), pose, width, height,
                                                                    renderer->status(settings).colour_bar_reserved_width);
        settings.cut_enabled = false;  // the whole model's extent
        renderer->render(settings, camera);
        const PixelBox box = model_pixels(pipeline::FrameReadback(*renderer).read_eclipse_ids(), width, height);
        const double fill_x = double(box.x1 - box.x0 + 1) / width, fill_y = double(box.y1 - box.y0 + 1) / height;
        std::cout << "  " << name << " " << width << "x" << height << " azimuth " << pose.azimuth_deg << " elevation "
                  << pose.elevation_deg << ": model box " << 100 * fill_x << "% x " << 100 * fill_y << "% of the panel\n";
        // Issue 15: the model's bounding box fills at least 85% of the panel's width or height.
        EXPECT_GE(std::max(fill_x, fill_y), 0.85) << name << " azimuth " << pose.azimuth_deg << " elevation " << pose.elevation_deg;
        // The model stays inside the panel and left of the colour bar: they never overlap.
        EXPECT_GE(box.x0, 0);
        EXPECT_LT(float(box.x1), bounds.x0) << "model reaches under the colour bar, " << name << " azimuth " << pose.azimuth_deg;
        // The viewer's control panel keeps the left columns too: the model is framed between.
        const float panel = 0.3f * float(width);
        renderer->render(settings, pipeline::make_orbit_camera(renderer->frame(), pose, width, height,
                                                               renderer->status(settings).colour_bar_reserved_width, panel));
        const PixelBox beside = model_pixels(pipeline::FrameReadback(*renderer).read_eclipse_ids(), width, height);
        EXPECT_GE(float(beside.x0), panel - 1.0f) << "model under the panel, " << name << " azimuth " << pose.azimuth_deg;
        EXPECT_LT(float(beside.x1), bounds.x0) << "model under the colour bar beside the panel, " << name;
        // An animation's date caption keeps the top rows: the model is framed below them.
        const float caption_rows = 0.1f * float(height);
        renderer->render(settings, pipeline::make_orbit_camera(renderer->frame(), pose, width, height,
                                                               renderer->status(settings).colour_bar_reserved_width, 0, caption_rows));
        const PixelBox below = model_pixels(pipeline::FrameReadback(*renderer).read_eclipse_ids(), width, height);
        EXPECT_GE(float(below.y0), caption_rows - 1.0f) << "model under the caption, " << name << " azimuth " << pose.azimuth_deg;
        EXPECT_LT(float(below.x1), bounds.x0) << "model under the colour bar below the caption, " << name;

        // The bar draws exactly where its layout says: over the background (the model stays clear
        // of the bar, checked above), the frame with and without it differs only inside the
        // layout's bounds, and does differ there (gradient, title, ticks). Model pixels are left
        // out: coplanar faces may rasterise either way from frame to frame on llvmpipe.
        settings.cut_enabled = true;
        settings.colour_bar = false;
        renderer->render(settings, camera);
        const gl::RgbaImage plain = pipeline::FrameReadback(*renderer).read_image();
        const std::vector<std::uint32_t> ids = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        settings.colour_bar = true;
        renderer->render(settings, camera);
        const gl::RgbaImage with_bar = pipeline::FrameReadback(*renderer).read_image();
        std::size_t outside = 0, inside = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                if (ids[std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)] != 0) continue;
                if (std::equal(plain.at(x, y), plain.at(x, y) + 3, with_bar.at(x, y))) continue;
                const bool in_bounds = float(x) + 1 > bounds.x0 && float(x) < bounds.x1 && float(y) + 1 > bounds.y0 && float(y) < bounds.y1;
                (in_bounds ? inside : outside) += 1;
            }
        EXPECT_EQ(outside, 0u) << "colour-bar pixels outside its layout, " << name;
        EXPECT_GT(inside, std::size_t(bar.gradient.width() * bar.gradient.height())) << name;
    }
}

// Figure panels are at least 1000 px wide (issue 15); at smaller sizes the bar's 7 px text takes
// a larger share of the width than 85% leaves.
TEST(FigureLayout, FramedModelFillsThePanelBesideTheColourBar) {
    check_framing(petra(), "petra", 1280, 720);
    check_framing(reek(), "reek", 1000, 750);
    check_framing(faulted_model_with_inactive_cells({30, 12, 10}, 0.2, 5), "faulted", 1000, 562);
}

TEST(FigureLayout, SilhouetteColourDiffersFromTheShellCutLines) {
    constexpr int width = 640, height = 480;
    auto renderer = make_renderer(petra(), width, height);
    const std::vector<float>& poro = *petra().property("PORO");
    renderer->select(grid::range_for_fraction(petra(), poro, "PORO", 0.01));
    pipeline::FrameSettings settings;
    settings.ssao = false;
    settings.colour_bar = false;
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), {35, 30, 0, glm::vec3(0)}, width, height);
    renderer->render(settings, camera);
    const gl::RgbaImage plain = pipeline::FrameReadback(*renderer).read_image();
    settings.silhouette = true;
    renderer->render(settings, camera);
    const gl::RgbaImage outlined = pipeline::FrameReadback(*renderer).read_image();
    const pipeline::IdImage ids = pipeline::RendererProbe(*renderer).read_ids();

    // Mean colours of the silhouette (pixels the silhouette changed) and of the shell-cut lines.
    glm::dvec3 silhouette(0), shell(0);
    std::size_t silhouette_count = 0, shell_count = 0, band_unchanged = 0;
    for (std::size_t i = 0; i < ids.cell.size(); ++i) {
        const int x = int(i % width), y = height - 1 - int(i / width);
        const std::uint8_t* before = plain.at(x, y);
        const std::uint8_t* after = outlined.at(x, y);
        const glm::dvec3 colour(after[0], after[1], after[2]);
        if (!std::equal(before, before + 3, after)) {
            silhouette += colour;
            ++silhouette_count;
        } else if (ids.flags[i] & pipeline::flag_shell_cut) {
            shell += colour;
            ++shell_count;
        }
    }
    // The doubled line leaves a gap: pixels between the inner and the outer line keep the scene.
    // Counted as non-primary pixels at distance 2 from a primary pixel that the silhouette kept.
    for (int y = 2; y < height - 2; ++y)
        for (int x = 2; x < width - 2; ++x) {
            const auto primary_at = [&](int px, int py) {
                return (ids.flags[std::size_t(height - 1 - py) * width + std::size_t(px)] & pipeline::flag_primary) != 0;
            };
            if (primary_at(x, y) || primary_at(x - 1, y) || primary_at(x + 1, y) || primary_at(x, y - 1) || primary_at(x, y + 1))
                continue;
            if (!(primary_at(x - 2, y) || primary_at(x + 2, y) || primary_at(x, y - 2) || primary_at(x, y + 2))) continue;
            band_unchanged += std::equal(plain.at(x, y), plain.at(x, y) + 3, outlined.at(x, y));
        }
    ASSERT_GT(silhouette_count, 200u);  // petra's 1% primaries are visible from here
    ASSERT_GT(shell_count, 200u);
    silhouette /= double(silhouette_count);
    shell /= double(shell_count);
    std::cout << "  silhouette mean colour " << silhouette.r << " " << silhouette.g << " " << silhouette.b << " ("
              << silhouette_count << " px), shell-cut lines " << shell.r << " " << shell.g << " " << shell.b << " ("
              << shell_count << " px), gap pixels " << band_unchanged << "\n";
    // 150 of 441 (the RGB cube's diagonal): a reader tells them apart at a glance (cyan vs red).
    EXPECT_GT(glm::length(silhouette - shell), 150.0);
    EXPECT_GT(silhouette.b, silhouette.r + 100);  // blue/cyan, as the domain experts asked
    EXPECT_GT(band_unchanged, silhouette_count / 10);  // the line is doubled, not a solid band
}

// An animation's date (FrameSettings::caption): dark text at the top-left corner, drawn where its layout
// says and nowhere else, gone again when the caption is emptied.
TEST(FigureLayout, CaptionDrawsItsTextOnlyInsideItsBox) {
    constexpr int width = 960, height = 540;
    auto renderer = make_renderer(petra(), width, height);
    pipeline::FrameSettings settings;
    settings.ssao = false;
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), {35, 30, 0, glm::vec3(0)}, width, height,
                                                                renderer->status(settings).colour_bar_reserved_width);
    renderer->render(settings, camera);
    const gl::RgbaImage plain = pipeline::FrameReadback(*renderer).read_image();
    const std::vector<std::uint32_t> ids = pipeline::FrameReadback(*renderer).read_eclipse_ids();
    const std::string text = "SWAT  2031-06-15  (step 2.5 of 0-30)";
    settings.caption = text;
    renderer->render(settings, camera);
    const gl::RgbaImage captioned = pipeline::FrameReadback(*renderer).read_image();
    settings.caption.clear();
    renderer->render(settings, camera);
    const gl::RgbaImage again = pipeline::FrameReadback(*renderer).read_image();
    const auto caption = annotation::place_caption(text, width, height, renderer->status(settings).colour_bar_reserved_width);
    ASSERT_TRUE(caption.has_value());
    // Model pixels are left out of the comparisons: coplanar faces may rasterise either way from
    // frame to frame on llvmpipe.
    std::size_t outside = 0, dark = 0, restored = 0, background = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* c = captioned.at(x, y);
            const bool in_box = float(x) + 1 > caption->box.x0 && float(x) < caption->box.x1 && float(y) + 1 > caption->box.y0 &&
                                float(y) < caption->box.y1;
            const auto is_dark = [](const std::uint8_t* rgb) { return rgb[0] < 60 && rgb[1] < 60 && rgb[2] < 60; };
            if (in_box) dark += is_dark(c) && !is_dark(plain.at(x, y));
            if (ids[std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)] != 0) continue;
            ++background;
            if (!in_box) outside += !std::equal(plain.at(x, y), plain.at(x, y) + 3, c);
            restored += std::equal(plain.at(x, y), plain.at(x, y) + 3, again.at(x, y));
        }
    EXPECT_EQ(outside, 0u) << "caption pixels outside its box";
    // The strokes cover about a fifth of the text's ink box; at least 10 dark pixels per glyph.
    EXPECT_GT(dark, 10 * text.size());
    // Capitals at least 2% of the height (the colour bar's), legible when the frame is a figure.
    EXPECT_GE(caption->line.scale * annotation::cap_height_px, 0.02f * height);
    EXPECT_EQ(restored, background) << "an empty caption draws nothing";

    // render and animate frame the model below the caption by the rows the renderer reserves for
    // it (the box and a margin as wide as above it): no model pixel in the box's rows.
    EXPECT_EQ(renderer->status(settings).caption_reserved_height, 0.0f) << "no caption, no rows";
    settings.caption = text;
    const float rows = renderer->status(settings).caption_reserved_height;
    EXPECT_FLOAT_EQ(rows, caption->box.y1 + caption->box.y0);
    renderer->render(settings, pipeline::make_orbit_camera(renderer->frame(), {35, 30, 0, glm::vec3(0)}, width, height,
                                                           renderer->status(settings).colour_bar_reserved_width, 0, rows));
    const PixelBox below = model_pixels(pipeline::FrameReadback(*renderer).read_eclipse_ids(), width, height);
    EXPECT_GE(float(below.y0), caption->box.y1) << "model under the caption";
}

TEST(FigureLayout, PrimaryPixelsShowTheirColourMapColour) {
    // The reader matches a primary's colour against the colour bar. The headlight shades every face
    // by its angle (0.35 + 0.65 |n.l|), so a pixel is compared with the map's colour at the cell's
    // value scaled to the pixel's brightness: what is left is a change of hue or saturation (white
    // edges, a saturation boost, blending with other colours). Edge pixels are left out.
    constexpr int width = 800, height = 450;
    auto renderer = make_renderer(petra(), width, height);
    const std::vector<float>& poro = *petra().property("PORO");
    renderer->select(grid::range_for_fraction(petra(), poro, "PORO", 0.01));
    const grid::PrimaryRange range = grid::active_value_range(petra(), poro, "PORO");
    pipeline::FrameSettings settings;  // the figures' defaults (SSAO on)
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), {35, 30, 0, glm::vec3(0)}, width, height,
                                                                renderer->status(settings).colour_bar_reserved_width);
    renderer->render(settings, camera);
    const gl::RgbaImage image = pipeline::FrameReadback(*renderer).read_image();
    const pipeline::IdImage ids = pipeline::RendererProbe(*renderer).read_ids();
    const std::vector<std::uint32_t> cells = pipeline::FrameReadback(*renderer).read_eclipse_ids();
    std::vector<double> distances, brightness;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (!(ids.flags[i] & pipeline::flag_primary) || (ids.flags[i] & pipeline::flag_edge) || cells[i] == 0) continue;
        const double t = std::clamp((poro[cells[i] - 1] - range.min) / (range.max - range.min), 0.0f, 1.0f);
        const std::array<std::uint8_t, 3> m = pipeline::colour_map_rgb(float(t));
        const std::uint8_t* p = image.at(int(i % width), height - 1 - int(i / width));
        const glm::dvec3 map(m[0], m[1], m[2]), shown(p[0], p[1], p[2]);
        const double k = std::clamp(glm::dot(shown, map) / glm::dot(map, map), 0.0, 1.5);
        distances.push_back(glm::length(shown - k * map));
        brightness.push_back(k);
    }
    ASSERT_GT(distances.size(), 2000u);  // petra's 1% primaries cover thousands of pixels here
    const double median_distance = metrics::median(distances), median_brightness = metrics::median(brightness);
    std::cout << "  primary pixels: median RGB distance " << median_distance << " to the colour map at their value, "
              << "brightness " << median_brightness << " of it (" << distances.size() << " px)\n";
    // 20 of 441 (the RGB cube's diagonal): the colour bar's entry at a glance; 8-bit rounding and
    // SSAO's grey add a few levels.
    EXPECT_LT(median_distance, 20.0);
    // And not so dark that the hue is lost: a face seen at the figures' 30 degree elevation gets
    // about two thirds of the light.
    EXPECT_GT(median_brightness, 0.5);
}

/// HSV saturation of an 8-bit RGB pixel.
double hsv_saturation(const std::uint8_t* p) {
    const int high = std::max({p[0], p[1], p[2]}), low = std::min({p[0], p[1], p[2]});
    return high == 0 ? 0.0 : double(high - low) / double(high);
}

TEST(FigureLayout, SaturationContrastSplitsTheColourBar) {
    // Under saturation contrast the secondaries are drawn desaturated: the bar's left half keeps
    // the primaries' (boosted) colours, its right half shows the secondaries' so a reader can
    // match either (fig. 9). The bar is found as the background pixels the contrast changes.
    constexpr int width = 800, height = 450;
    auto renderer = make_renderer(petra(), width, height);
    renderer->select(grid::range_for_fraction(petra(), *petra().property("PORO"), "PORO", 0.01));
    pipeline::FrameSettings settings;
    settings.ssao = false;  // speed; the bar does not depend on it
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), {35, 30, 0, glm::vec3(0)}, width, height,
                                                                renderer->status(settings).colour_bar_reserved_width);
    renderer->render(settings, camera);
    const gl::RgbaImage plain = pipeline::FrameReadback(*renderer).read_image();
    const std::vector<std::uint32_t> ids = pipeline::FrameReadback(*renderer).read_eclipse_ids();
    settings.saturation = true;
    renderer->render(settings, camera);
    const gl::RgbaImage contrast = pipeline::FrameReadback(*renderer).read_image();
    std::vector<std::pair<int, double>> changed;  // x, saturation with contrast / without
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (ids[std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)] != 0) continue;
            const double before = hsv_saturation(plain.at(x, y));
            if (before > 0.2 && !std::equal(plain.at(x, y), plain.at(x, y) + 3, contrast.at(x, y)))
                changed.emplace_back(x, hsv_saturation(contrast.at(x, y)) / before);
        }
    ASSERT_GT(changed.size(), 500u) << "the colour bar's gradient changes under saturation contrast";
    const auto [low, high] = std::minmax_element(changed.begin(), changed.end());
    const double middle = 0.5 * (low->first + high->first);
    std::vector<double> left, right;
    for (const auto& [x, ratio] : changed) (x < middle ? left : right).push_back(ratio);
    const double left_ratio = metrics::median(left), right_ratio = metrics::median(right);
    std::cout << "  colour bar saturation with contrast / without: left half " << left_ratio << ", right half "
              << right_ratio << " (factors " << settings.saturation_primary << ", " << settings.saturation_secondary << ")\n";
    // The factors within 8-bit rounding (the saturated end of the map clamps at 1 on the left).
    EXPECT_GT(left_ratio, 1.0);
    EXPECT_NEAR(right_ratio, settings.saturation_secondary, 0.05);
}

}  // namespace
}  // namespace cutaway::test
