// Colouring values sent at 16 bits (ValueStorage::unorm16, what smooth animations send every
// frame) must colour the frame as the float values do, cost 2 bytes per active cell, and refuse a
// primary selection by range (which would compare quantised values).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

constexpr int width = 320, height = 240;

gl::RgbaImage frame_coloured(pipeline::CutawayRenderer& renderer, const std::vector<float>& values,
                             const annotation::ColourBarLabel& label, pipeline::ValueStorage storage) {
    renderer.set_colouring(values, label, storage);
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer.frame(), {35, 30, 0}, width, height);
    pipeline::FrameSettings settings;
    settings.ssao = false;
    renderer.render(settings, camera);
    return pipeline::FrameReadback(renderer).read_image();
}

TEST(QuantisedValues, ColourTheFrameAsFloatValuesDo) {
    const grid::CornerPointGrid& grid = reek();
    auto renderer = make_renderer(grid, width, height);
    std::mt19937 random(7);
    renderer->select(random_primaries(grid, random));
    const std::vector<float>& poro = *grid.property("PORO");
    const grid::PrimaryRange range = grid::active_value_range(grid, poro, "PORO");
    // A colour range narrower than the values' span: the codes span every value, the colour map
    // clamps, as with float values.
    const annotation::ColourBarLabel label{"PORO", range.min + 0.1f * (range.max - range.min), range.max, "frac"};
    const gl::RgbaImage exact = frame_coloured(*renderer, poro, label, pipeline::ValueStorage::float32);
    const std::size_t before = renderer->status({}).uploaded_bytes;
    const gl::RgbaImage coded = frame_coloured(*renderer, poro, label, pipeline::ValueStorage::unorm16);
    EXPECT_EQ(renderer->status({}).uploaded_bytes - before, 2 * grid.active_count());
    // A code is within span / 131070 of its value: under a 256-texel colour map that moves a
    // colour by at most one step of 8 bits where the linear filter crosses a texel, and lighting
    // multiplies it by at most 1; so 1 level, plus 1 for the rounding of the lit colour.
    int largest = 0;
    std::size_t differing = 0;
    for (std::size_t b = 0; b < exact.pixels.size(); ++b) {
        const int d = std::abs(int(exact.pixels[b]) - int(coded.pixels[b]));
        largest = std::max(largest, d);
        differing += d > 0;
    }
    EXPECT_LE(largest, 2) << differing << " channel values differ";
    // Back to float values: the same frame as before, bit for bit.
    EXPECT_EQ(frame_coloured(*renderer, poro, label, pipeline::ValueStorage::float32).pixels, exact.pixels);
}

TEST(QuantisedValues, RefuseAPrimarySelectionByRange) {
    const grid::CornerPointGrid& grid = reek();
    auto renderer = make_renderer(grid, width, height);
    const std::vector<float>& poro = *grid.property("PORO");
    const grid::PrimaryRange range = grid::range_for_fraction(grid, poro, "PORO", 0.05);
    renderer->set_colouring(poro, {"PORO", range.min, range.max, ""}, pipeline::ValueStorage::unorm16);
    EXPECT_THROW(renderer->select(pipeline::Primaries(range, std::nullopt)), std::logic_error);
    renderer->select(std::vector<std::uint8_t>(grid.cell_count(), 0));  // flags are fine
    renderer->set_colouring(poro, {"PORO", range.min, range.max, ""});
    EXPECT_NO_THROW(renderer->select(pipeline::Primaries(range, std::nullopt)));
}

}  // namespace
}  // namespace cutaway::test
