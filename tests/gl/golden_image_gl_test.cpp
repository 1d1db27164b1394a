// A few whole frames compared with committed PNGs. Each case states its threshold and why.
// Regenerate after an intended change with CUTAWAY_UPDATE_GOLDEN=1 (writes tests/gl/golden/).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "gl/image.h"
#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

struct GoldenCase {
    const char* name;
    bool reek;                 ///< Reek, else petra
    pipeline::FrameSettings settings;
    pipeline::OrbitPose pose;
    double max_fraction_off;   ///< of pixels differing by more than 24/255 in a channel
};

std::filesystem::path golden_path(const char* name) {
    return std::filesystem::path(CUTAWAY_SOURCE_DIR) / "tests/gl/golden" / (std::string(name) + ".png");
}

/// Fraction of pixels with some channel off by more than `levels`.
double fraction_off(const gl::RgbaImage& a, const gl::RgbaImage& b, int levels) {
    std::size_t off = 0;
    for (std::size_t i = 0; i < a.pixels.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])) > levels) {
                ++off;
                break;
            }
    return double(off) / double(a.pixels.size() / 4);
}

void check_golden(const GoldenCase& golden) {
    const grid::CornerPointGrid& grid = golden.reek ? reek() : petra();
    auto renderer = make_renderer(grid, 320, 240);
    const std::vector<float>& poro = *grid.property("PORO");
    renderer->select(grid::select_primaries(grid, poro, "PORO", grid::range_for_fraction(grid, poro, "PORO", 0.01)));
    renderer->render(golden.settings, pipeline::make_orbit_camera(renderer->frame(), golden.pose, 320, 240,
                                                                  renderer->status(golden.settings).colour_bar_reserved_width));
    const gl::RgbaImage image = pipeline::FrameReadback(*renderer).read_image();
    const std::filesystem::path path = golden_path(golden.name);
    if (const char* update = std::getenv("CUTAWAY_UPDATE_GOLDEN"); update && std::string(update) == "1") {
        gl::write_png(image, path);
        GTEST_SKIP() << "wrote " << path;
    }
    const gl::RgbaImage expected = gl::read_png(path);
    ASSERT_EQ(expected.width, image.width);
    ASSERT_EQ(expected.height, image.height);
    const double off = fraction_off(image, expected, 24);
    std::cout << golden.name << ": " << off * 100 << "% of pixels off by more than 24/255\n";
    EXPECT_LE(off, golden.max_fraction_off) << "compare " << path << " with a fresh render";
}

pipeline::FrameSettings full_pipeline() {
    pipeline::FrameSettings s;  // the paper's set-up: 9x9 mean filter, SSAO, ray-cast borders
    return s;
}

pipeline::FrameSettings expert_options() {
    pipeline::FrameSettings s;
    pipeline::set_aperture_180(s);
    s.hide_internal_lines = true;
    s.border = pipeline::BorderMode::threshold;
    s.ssao = false;
    s.mean_filter = 0;
    return s;
}

pipeline::FrameSettings primaries_highlighted() {
    pipeline::FrameSettings s;
    s.saturation = true;
    s.silhouette = true;
    s.ssao = false;
    return s;
}

// llvmpipe on the same Mesa gives the same image bit for bit; another CPU (vector width) or Mesa
// patch release may round differently along triangle edges and in SSAO's depth comparisons, which
// moves edge and border pixels. 1% of pixels (768 of 76,800) allows that while a real change
// (a missing stage, a moved cut) changes tens of percent.
TEST(GoldenImages, PetraFullPipeline) { check_golden({"petra_full_pipeline", false, full_pipeline(), {35, 30, 0, glm::vec3(0)}, 0.01}); }

// No SSAO, no filter: only rasterisation differences remain, so the same 1%.
TEST(GoldenImages, ReekExpertOptions) { check_golden({"reek_aperture180_hidden_lines", true, expert_options(), {210, 40, 0, glm::vec3(0)}, 0.01}); }

// The silhouette is a 3-pixel band around every primary pixel; one-pixel shifts of primary
// edges move up to 3 band pixels each, so this case allows 2%.
TEST(GoldenImages, PetraSaturationAndSilhouette) {
    check_golden({"petra_saturation_silhouette", false, primaries_highlighted(), {120, 50, 0, glm::vec3(0)}, 0.02});
}

}  // namespace
}  // namespace cutaway::test
