// Wells drawn as tubes (issue 45): every SPE9 well drawn with its own id and colour and labelled
// inside the image, a tube visible wherever its wellhead is in view, no well pixel reported as a cell.
#include <gtest/gtest.h>

#include <random>

#include "app_core/frame_wells.h"
#include "app_core/model_source.h"
#include "common/shared_constants.h"
#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

using shared::flag_well, shared::well_index_shift;

constexpr int width = 1920, height = 1080;

struct Spe9Wells {
    app::LoadedModel model;
    pipeline::WellSet wells;
};

/// SPE9's grid (24 x 25 x 15) with the 26 wells of its deck, read once.
const Spe9Wells& spe9() {
    static const Spe9Wells scene = [] {
        const std::string data = std::string(CUTAWAY_SHARED_DATA) + "/opm/spe9/";
        Spe9Wells s{app::load_model({data + "SPE9.GRDECL"}, std::size_t(4) << 30), {}};
        s.wells = app::frame_wells(s.model, {data + "SPE9.DATA"}, 0, -1);
        return s;
    }();
    return scene;
}

/// Pixels of each well's tube in the last frame (by the index its flags carry).
std::vector<std::size_t> well_pixels(const pipeline::CutawayRenderer& renderer, std::size_t well_count) {
    const pipeline::IdImage ids = pipeline::FrameReadback(renderer).read_ids();
    std::vector<std::size_t> counts(well_count, 0);
    for (std::size_t p = 0; p < ids.flags.size(); ++p)
        if (ids.flags[p] & flag_well) {
            EXPECT_EQ(ids.cell[p], 0u) << "a well pixel shows no cell";
            const std::size_t index = ids.flags[p] >> well_index_shift;
            if (index < well_count) ++counts[index];
        }
    return counts;
}

pipeline::FrameSettings quick_settings() {
    pipeline::FrameSettings s;
    s.ssao = false;  // the colour test reads the tubes' own shading
    s.mean_filter = 0;
    return s;
}

TEST(Wells, EverySpe9WellIsDrawnInItsColourAndLabelledInsideTheImage) {
    const Spe9Wells& s = spe9();
    ASSERT_EQ(s.wells.wells.size(), 26u);
    pipeline::CutawayRenderer renderer(GlEnvironment::shaders(), s.model.grid, 0, width, height);
    renderer.set_wells(s.wells);
    const pipeline::FrameSettings settings = quick_settings();
    const float bar = renderer.status(settings).colour_bar_reserved_width;
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer.frame(), {}, width, height, bar);
    renderer.render(settings, camera);
    const std::vector<std::size_t> counts = well_pixels(renderer, 26);
    const gl::RgbaImage image = pipeline::FrameReadback(renderer).read_image();
    const pipeline::IdImage ids = pipeline::FrameReadback(renderer).read_ids();
    // The final image's rows run top to bottom, the id image's bottom to top.
    std::vector<double> red(26, 0), blue(26, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint32_t flags = ids.flags[std::size_t(height - 1 - y) * width + std::size_t(x)];
            if (!(flags & flag_well)) continue;
            const std::uint8_t* rgba = &image.pixels[4 * (std::size_t(y) * width + std::size_t(x))];
            red[flags >> well_index_shift] += rgba[0];
            blue[flags >> well_index_shift] += rgba[2];
        }
    for (std::size_t w = 0; w < 26; ++w) {
        const std::string& name = s.wells.wells[w].name;
        EXPECT_GT(counts[w], 0u) << name << " is drawn";
        // Injector INJE1 blue, producers red-orange (labels are drawn over the final image, so
        // this compares sums over each tube's pixels, which the small label boxes cannot flip).
        if (name == "INJE1") EXPECT_GT(blue[w], red[w]) << name;
        else EXPECT_GT(red[w], blue[w]) << name;
    }
    const std::vector<annotation::PlacedLabel> labels = pipeline::well_label_layout(renderer.status().well_heads, camera, bar);
    EXPECT_EQ(labels.size(), 26u) << "every wellhead is in view: every well is named";
    std::size_t overlapping = 0;
    for (std::size_t a = 0; a < labels.size(); ++a) {
        const annotation::PixelRect& box = labels[a].box;
        EXPECT_TRUE(box.x0 >= 0 && box.y0 >= 0 && box.x1 <= float(width) - bar && box.y1 <= float(height))
            << labels[a].line.text << " at " << box.x0 << ", " << box.y0 << " - " << box.x1 << ", " << box.y1;
        for (std::size_t b = a + 1; b < labels.size(); ++b) overlapping += box.overlaps(labels[b].box);
    }
    EXPECT_EQ(overlapping, 0u) << "labels placed clear of each other";
}

TEST(Wells, AFramedCameraShowsEveryWellheadWithTheModel) {
    // Wellheads stand above the model's top; a camera framed on the model alone cut the tallest
    // wells at the image's top edge (referee round 5: PROD1 in wells_waterflood). Framed with its
    // wells, every wellhead projects inside the image, beside the colour bar, at any orbit pose.
    const Spe9Wells& s = spe9();
    pipeline::CutawayRenderer renderer(GlEnvironment::shaders(), s.model.grid, 0, 640, 360);
    renderer.set_wells(s.wells);
    ASSERT_EQ(renderer.frame().drawn_with.size(), s.wells.wells.size());
    const float bar = renderer.status(quick_settings()).colour_bar_reserved_width;
    for (const pipeline::OrbitPose pose : {pipeline::OrbitPose{35, 30, 0, glm::vec3(0)}, pipeline::OrbitPose{215, 40, 0, glm::vec3(0)},
                                           pipeline::OrbitPose{120, 15, 0, glm::vec3(0)}, pipeline::OrbitPose{300, 70, 0, glm::vec3(0)}}) {
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer.frame(), pose, 640, 360, bar);
        for (const pipeline::WellHead& head : renderer.status().well_heads) {
            const glm::vec4 clip = camera.view_projection() * glm::vec4(head.position, 1.0f);
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            const float x = (0.5f * ndc.x + 0.5f) * 640.0f;
            EXPECT_TRUE(clip.w > 0 && std::abs(ndc.y) <= 1.0f && x >= 0.0f && x <= 640.0f - bar)
                << head.name << " at azimuth " << pose.azimuth_deg << ": ndc " << ndc.x << ", " << ndc.y;
        }
    }
    renderer.set_wells({});
    EXPECT_TRUE(renderer.frame().drawn_with.empty()) << "no wells, the model alone framed";
}

TEST(Wells, AWellWhoseHeadIsOutOfViewIsNamedWhereItComesIntoView) {
    // A well standing above the top of the image (a tall well, a framed model): its name is placed
    // where its first segment enters the image instead of being left out with its head.
    const Spe9Wells& s = spe9();
    pipeline::CutawayRenderer renderer(GlEnvironment::shaders(), s.model.grid, 0, 640, 360);
    renderer.set_wells(s.wells);
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer.frame(), {}, 640, 360);
    std::vector<pipeline::WellHead> heads = {renderer.status().well_heads.front()};
    pipeline::WellHead& head = heads.front();
    // Raised until it projects above the image: up the camera's own up axis from where it was.
    const glm::vec3 up = glm::normalize(glm::vec3(glm::inverse(camera.view) * glm::vec4(0, 1, 0, 0)));
    head.next = head.position;
    head.position += up * 10.0f * float(renderer.frame().radius());
    const std::vector<annotation::PlacedLabel> labels = pipeline::well_label_layout(heads, camera, 0);
    ASSERT_EQ(labels.size(), 1u) << head.name << " is named though its head is out of view";
    EXPECT_GE(labels.front().anchor_y, 0.0f);
}

TEST(Wells, ATubeIsVisibleWhereverItsWellheadIsInView) {
    // Occlusion: wellheads stand above the model's top (wells::wellhead_level), so from an eye
    // above that level the line of sight to a wellhead passes above every cell, cut or not: only
    // another tube could hide it, and SPE9's wells stand a cell or more apart. Poses whose eye is
    // below the wellheads are skipped (counted, so that the test cannot pass on none).
    const Spe9Wells& s = spe9();
    pipeline::CutawayRenderer renderer(GlEnvironment::shaders(), s.model.grid, 0, 640, 360);
    renderer.set_wells(s.wells);
    std::mt19937 random(45);
    const pipeline::FrameSettings settings = quick_settings();
    int poses_checked = 0, heads_checked = 0;
    for (int trial = 0; trial < 8; ++trial) {
        pipeline::OrbitPose pose = random_pose(random);
        // Some poses closer than framed, so that some wellheads fall outside the image.
        if (trial % 2) pose.distance = 0.6f * renderer.frame().radius() / std::tan(0.5f * glm::radians(pipeline::default_fovy_deg));
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer.frame(), pose, 640, 360);
        if (camera.eye.z <= renderer.status().well_heads.front().position.z) continue;
        ++poses_checked;
        renderer.render(settings, camera);
        const std::vector<std::size_t> counts = well_pixels(renderer, s.wells.wells.size());
        for (std::size_t w = 0; w < s.wells.wells.size(); ++w) {
            const glm::vec4 clip = camera.view_projection() * glm::vec4(renderer.status().well_heads[w].position, 1.0f);
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            if (clip.w <= 0 || std::abs(ndc.x) > 1 || std::abs(ndc.y) > 1 || std::abs(ndc.z) > 1) continue;
            ++heads_checked;
            EXPECT_GT(counts[w], 0u) << s.wells.wells[w].name << ", pose " << trial << ": azimuth " << pose.azimuth_deg
                                     << ", elevation " << pose.elevation_deg;
        }
    }
    EXPECT_GE(poses_checked, 4);
    EXPECT_GE(heads_checked, 60);
}

}  // namespace
}  // namespace cutaway::test
