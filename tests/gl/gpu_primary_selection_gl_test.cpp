// The primary selection on the GPU (cutaway/selection/gpu_primary_selection.h) against the CPU
// reference: the bits must equal grid::select_primaries' flags, and the primary cell and face
// lists must equal build_face_lists' lists element for element (same order), on models with
// inactive cells and faults, for random ranges, IJK boxes (also partly or wholly outside the
// grid) and random flag sets. Exact equality: both sides run the same integer logic on the same
// float comparisons, so there is no tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "cutaway/grid_buffers.h"
#include "cutaway/selection/gpu_primary_selection.h"
#include "cutaway/selection/primary_centroid.h"
#include "grid/cell_geometry.h"
#include "gl_test_support.h"

namespace cutaway::test {
namespace {

std::vector<std::uint32_t> read_list(const pipeline::FaceBuffer& list) {
    std::vector<std::uint32_t> values(list.count);
    if (!values.empty()) glGetNamedBufferSubData(list.buffer.id(), 0, GLsizeiptr(values.size() * 4), values.data());
    return values;
}

/// Layout, GPU buffers and selection of one model, coloured by `values` (one per Eclipse cell).
struct SelectionScene {
    const grid::CornerPointGrid& grid;
    pipeline::ModelFrame frame;
    pipeline::GridLayout layout;
    pipeline::GridBuffers buffers;
    pipeline::GpuPrimarySelection selection;

    SelectionScene(const grid::CornerPointGrid& g, const std::vector<float>& values)
        : grid(g),
          frame(pipeline::make_model_frame(g, 0.0)),
          layout(pipeline::build_grid_layout(g, grid::FaceClassification(g, grid::default_face_tolerance(g)), frame)),
          buffers(layout, g.zcorn(), frame),
          selection(GlEnvironment::shaders(), layout, g) {
        std::vector<float> compact(layout.cells.size());
        for (std::size_t c = 0; c < compact.size(); ++c) compact[c] = values[layout.cells[c] & 0x7fffffffu];
        buffers.set_values(compact);
    }

    /// The GPU's bits and lists equal the CPU reference's for `flags`.
    void expect_lists_match(const std::vector<std::uint8_t>& flags, const std::string& what) const {
        const pipeline::FaceLists cpu = pipeline::build_face_lists(grid, layout, flags, false);
        EXPECT_EQ(buffers.read_primary_bits(), pipeline::primary_bits(layout, flags)) << what;
        EXPECT_EQ(read_list(buffers.primary_cells()), cpu.primary_cells) << what;
        EXPECT_EQ(read_list(buffers.primary_faces()), cpu.primary) << what;
    }
};

/// Values with ties and a spread: the cell index modulo a prime, plus a fraction.
std::vector<float> tied_values(std::size_t cells) {
    std::vector<float> values(cells);
    for (std::size_t c = 0; c < cells; ++c) values[c] = float(c % 101) + (c % 3 == 0 ? 0.5f : 0.0f);
    return values;
}

grid::IjkBox random_box(const grid::GridDims& dims, std::mt19937& random) {
    // Corners from -2 to n + 1: boxes partly outside the grid, and crossed (empty) boxes.
    const auto coordinate = [&](int n) { return int(random() % unsigned(n + 4)) - 2; };
    return {coordinate(dims.nx), coordinate(dims.ny), coordinate(dims.nz),
            coordinate(dims.nx), coordinate(dims.ny), coordinate(dims.nz)};
}

void check_model(const grid::CornerPointGrid& grid, unsigned seed) {
    const std::vector<float> values = tied_values(grid.cell_count());
    SelectionScene scene(grid, values);
    std::mt19937 random(seed);
    for (int round = 0; round < 12; ++round) {
        const float low = float(random() % 101), high = low + float(random() % 30);
        std::optional<grid::IjkBox> box;
        if (round % 3 != 0) box = random_box(grid.dims(), random);
        scene.selection.select_range(scene.buffers, {low, high}, box);
        const auto flags = grid::select_primaries(grid, values, "V", {low, high}, std::nullopt);
        std::vector<std::uint8_t> expected = flags;
        if (box)
            for (std::size_t c = 0; c < expected.size(); ++c) expected[c] &= box->contains(grid::cell_ijk(grid.dims(), c)) ? 1 : 0;
        scene.expect_lists_match(expected, "range [" + std::to_string(low) + ", " + std::to_string(high) + "] round " +
                                               std::to_string(round));
        std::vector<std::uint8_t> random_flags(grid.cell_count(), 0);
        for (std::size_t c = 0; c < random_flags.size(); ++c) random_flags[c] = grid.active(c) && random() % 4 == 0;
        scene.selection.select_bits(scene.buffers, pipeline::primary_bits(scene.layout, random_flags));
        scene.expect_lists_match(random_flags, "random flags round " + std::to_string(round));
    }
}

TEST(GpuPrimarySelection, PetraRangesBoxesAndFlagsEqualTheCpuLists) { check_model(petra(), 1); }

TEST(GpuPrimarySelection, FaultedModelWithInactiveCellsEqualsTheCpuLists) {
    // 3059 cells: the last word of 32 cells is partly filled.
    const grid::CornerPointGrid grid = faulted_model_with_inactive_cells({23, 19, 7}, 0.3, 11);
    ASSERT_LT(grid.active_count(), grid.cell_count());
    check_model(grid, 2);
}

TEST(GpuPrimarySelection, ZcornWithGapsBetweenLayersEqualsTheCpuLists) {
    // The shaders take a cell's IJK from its top-face texel, whose layer stride is two plane slots
    // when the layers do not share their interfaces (ZCORN's full layout): the same model with
    // every bottom plane lowered a little.
    const grid::CornerPointGrid compact = faulted_model_with_inactive_cells({23, 19, 7}, 0.3, 12);
    std::vector<double> depths(compact.dims().zcorn_value_count());
    const std::size_t plane = 4 * std::size_t(compact.dims().nx) * std::size_t(compact.dims().ny);
    for (std::size_t n = 0; n < depths.size(); ++n) depths[n] = compact.zcorn().value(n) + double(n / plane % 2) * 0.25;
    grid::CornerPointGrid gapped(compact.dims(), std::vector<double>(compact.coord()),
                                 grid::ZcornStore::from_values(compact.dims(), depths), std::vector<std::uint8_t>(compact.actnum()));
    gapped.set_property("PORO", std::vector<float>(*compact.property("PORO")));
    ASSERT_FALSE(gapped.zcorn().is_compact());
    check_model(gapped, 3);
}

TEST(GpuPrimarySelection, NanValuesAreNeverPrimaryAndEmptySelectionsHaveEmptyLists) {
    const grid::CornerPointGrid& grid = petra();
    std::vector<float> values = tied_values(grid.cell_count());
    for (std::size_t c = 0; c < values.size(); c += 7) values[c] = std::numeric_limits<float>::quiet_NaN();
    SelectionScene scene(grid, values);
    scene.selection.select_range(scene.buffers, {-1e30f, 1e30f}, std::nullopt);
    std::vector<std::uint8_t> expected(grid.cell_count(), 0);
    for (std::size_t c = 0; c < expected.size(); ++c) expected[c] = grid.active(c) && !std::isnan(values[c]);
    scene.expect_lists_match(expected, "everything but NaN");
    scene.selection.select_range(scene.buffers, {1000, 2000}, std::nullopt);
    EXPECT_EQ(scene.buffers.primary_cells().count, 0u);
    EXPECT_EQ(scene.buffers.primary_faces().count, 0u);
}

/// Render-space mean of the flagged cells' centres in double from the CPU grid (the reference).
glm::dvec3 cpu_centroid(const grid::CornerPointGrid& grid, const pipeline::ModelFrame& frame,
                        const std::vector<std::uint8_t>& flags) {
    glm::dvec3 sum(0);
    std::size_t count = 0;
    for (std::size_t c = 0; c < flags.size(); ++c) {
        if (!flags[c]) continue;
        const grid::CellIjk ijk = grid::cell_ijk(grid.dims(), c);
        sum += glm::dvec3(frame.to_render(grid::cell_centre(grid::cell_corners(grid, ijk.i, ijk.j, ijk.k))));
        ++count;
    }
    return count ? sum / double(count) : sum;
}

TEST(PrimaryCentroid, GpuCentroidEqualsTheCpuMeanOfCellCentres) {
    // The GPU rebuilds corners from float depths and sums 256 centres in float; against the
    // double reference that leaves float rounding: 1e-5 of the model's radius bounds it (float
    // holds 7 digits; partial sums of 256 lose at most 8 bits of it).
    const grid::CornerPointGrid faulted = faulted_model_with_inactive_cells({23, 19, 7}, 0.3, 11);
    for (const grid::CornerPointGrid* grid : {&petra(), &faulted}) {
        SelectionScene scene(*grid, tied_values(grid->cell_count()));
        pipeline::PrimaryCentroid centroid(GlEnvironment::shaders());
        std::mt19937 random(5);
        for (int round = 0; round < 6; ++round) {
            std::vector<std::uint8_t> flags(grid->cell_count(), 0);
            // round 0: one cell; then denser sets up to every active cell (more than 256: several groups).
            for (std::size_t c = 0; c < flags.size(); ++c)
                flags[c] = grid->active(c) && (round == 5 || (round == 0 ? c == 1234 : random() % (8u >> (round % 4)) == 0));
            scene.selection.select_bits(scene.buffers, pipeline::primary_bits(scene.layout, flags));
            const glm::dvec3 expected = cpu_centroid(*grid, scene.frame, flags);
            const pipeline::CentreSum sum = centroid.centre_sum(scene.buffers);
            ASSERT_EQ(sum.count, scene.buffers.primary_cells().count) << "round " << round;
            const glm::dvec3 got = sum.sum / double(std::max<std::uint64_t>(sum.count, 1));
            EXPECT_LE(glm::length(got - expected), 1e-5 * scene.frame.radius()) << "round " << round;
        }
        scene.selection.select_range(scene.buffers, {1000, 2000}, std::nullopt);
        EXPECT_EQ(centroid.centre_sum(scene.buffers).count, 0u) << "no primary";
    }
}

TEST(PrimaryCentroid, ReleasedCornerDepthsAreRefusedNotRead) {
    grid::CornerPointGrid grid = faulted_model_with_inactive_cells({6, 5, 3}, 0.2, 3);
    ASSERT_TRUE(grid.has_corner_depths());
    grid.release_corner_depths();
    EXPECT_FALSE(grid.has_corner_depths());
    EXPECT_THROW(grid::cell_corners(grid, 0, 0, 0), std::logic_error);
}

}  // namespace
}  // namespace cutaway::test
