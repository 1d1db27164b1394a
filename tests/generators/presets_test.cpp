// The paper's models by cell count, written and read back by our reader unchanged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "generator_test_support.h"
#include "grid/cell_geometry.h"
#include "grid/grdecl_reader.h"

namespace cutaway::generators {
namespace {

namespace fs = std::filesystem;

struct PaperModel {
    const char* name;
    grid::GridDims dims;
};

class PaperPresets : public ::testing::TestWithParam<PaperModel> {};

TEST_P(PaperPresets, CellCountAndRoundTrip) {
    const GeneratorParameters p = find_preset(GetParam().name);
    ASSERT_EQ(p.dims, GetParam().dims);
    const GeneratedModel model = testing::generate_quietly(p);
    const grid::CornerPointGrid& ours = model.grid;
    EXPECT_EQ(model.report.active_cells, ours.active_count());
    EXPECT_GT(ours.active_count(), ours.cell_count() * 8 / 10);
    EXPECT_LT(ours.active_count(), ours.cell_count());
    EXPECT_EQ(model.report.inverted_cells + model.report.degenerate_cells + model.report.pinched_cells +
                  model.report.clustered_inactive,
              ours.cell_count() - ours.active_count());

    const fs::path path = fs::temp_directory_path() / (std::string("cutaway_preset_") + GetParam().name + ".grdecl");
    {
        std::ofstream out(path, std::ios::binary);
        out << testing::grdecl_text(p);
    }
    const grid::CornerPointGrid read = grid::load_grdecl({path});
    fs::remove(path);
    ASSERT_EQ(read.dims(), p.dims);
    EXPECT_EQ(read.active_count(), ours.active_count());
    EXPECT_TRUE(read.zcorn().is_compact());
    ASSERT_EQ(read.step_count("SWAT"), std::size_t(p.time_steps));
    ASSERT_NE(read.int_property("FACIES"), nullptr);
    for (const char* name : {"PORO", "PERMX", "NTG"}) {
        ASSERT_NE(read.property(name), nullptr) << name;
        EXPECT_EQ(*read.property(name), *ours.property(name)) << name;
    }
    const grid::GridDims& d = p.dims;
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i)
                ASSERT_EQ(grid::cell_volume(grid::cell_corners(read, i, j, k)),
                          grid::cell_volume(grid::cell_corners(ours, i, j, k)));
}

INSTANTIATE_TEST_SUITE_P(Paper, PaperPresets,
                         ::testing::Values(PaperModel{"zaphirus", {30, 50, 5}}, PaperModel{"petra", {39, 42, 20}},
                                           PaperModel{"opharine", {95, 80, 10}},
                                           PaperModel{"sapphire", {124, 84, 20}}),
                         [](const ::testing::TestParamInfo<PaperModel>& info) { return std::string(info.param.name); });

TEST(ScalePresets, CellCounts) {
    EXPECT_EQ(find_preset("scale-1m").dims.cell_count(), 1000000u);
    EXPECT_EQ(find_preset("scale-10m").dims.cell_count(), 10000000u);
    EXPECT_THROW(find_preset("atlantis"), std::invalid_argument);
}

TEST(PinchOuts, FractionIsHonoured) {
    GeneratorParameters p = testing::small_parameters();
    p.pinch_out_fraction = 0.1;
    p.inactive_fraction = 0;
    const GeneratedModel model = testing::generate_quietly(p);
    const double share = double(model.report.pinched_cells) / double(model.report.cells);
    EXPECT_NEAR(share, 0.1, 0.03);
    p.pinch_out_fraction = 0;
    EXPECT_EQ(testing::generate_quietly(p).report.pinched_cells, 0u);
}

TEST(InactiveCells, FractionIsHonoured) {
    GeneratorParameters p = testing::small_parameters();
    p.pinch_out_fraction = 0;
    p.inactive_fraction = 0.2;
    const GeneratedModel model = testing::generate_quietly(p);
    EXPECT_NEAR(double(model.report.clustered_inactive) / double(model.report.cells), 0.2, 0.01);
}

}  // namespace
}  // namespace cutaway::generators
