#include <gtest/gtest.h>

#include "grid/cell_geometry.h"
#include "grid/grdecl_reader.h"
#include "test_files.h"

using namespace cutaway::grid;
using cutaway::test::ScratchDir;

namespace {

// A 2 x 1 x 1 grid written with the syntax variants the reader must understand.
const char* two_cells = R"(-- a comment line
NOECHO
SPECGRID
 2 1 1 1 F / -- trailing comment
COORD
 0 0 0  0 0 10   1 0 0  1 0 10   2 0 0 2 0 10
 0 1 0  0 1 10   1 1 0  1 1 10   2 1 0 2 1 10 /
ZCORN
 8*0 8*1 /
ACTNUM
 2*1 /
MAPUNITS
 'METRES  ' /
ECHO
)";

}  // namespace

TEST(GrdeclReader, ReadsRepeatsCommentsQuotesAndEchoKeywords) {
    GrdeclReader reader;
    reader.read_text(two_cells, "two_cells");
    const CornerPointGrid grid = reader.finish();
    EXPECT_EQ(grid.dims(), (GridDims{2, 1, 1}));
    EXPECT_EQ(grid.active_count(), 2u);
    EXPECT_EQ(grid.metadata().map_units, "METRES");
    EXPECT_DOUBLE_EQ(cell_volume(cell_corners(grid, 1, 0, 0)), 1.0);
    EXPECT_TRUE(reader.warnings().empty());
}

TEST(GrdeclReader, ReekGridWithPoroOnOneGrid) {
    std::vector<std::string> warnings;
    const CornerPointGrid grid = load_grdecl({cutaway::test::reek_grid(), cutaway::test::reek_poro()}, {}, &warnings);
    EXPECT_EQ(grid.dims(), (GridDims{40, 64, 14}));
    EXPECT_EQ(grid.active_count(), 35838u);  // DATA.md, as OPM reports
    ASSERT_NE(grid.property("PORO"), nullptr);
    EXPECT_FLOAT_EQ((*grid.property("PORO"))[0], 0.177493915f);
    ASSERT_TRUE(grid.metadata().mapaxes.has_value());
    EXPECT_DOUBLE_EQ((*grid.metadata().mapaxes)[0], 456510.625);
    EXPECT_EQ(grid.metadata().grid_unit, "METRES");
    EXPECT_EQ(grid.metadata().gdorient, (std::vector<std::string>{"INC", "INC", "INC", "DOWN", "RIGHT"}));
    EXPECT_TRUE(grid.zcorn().is_compact());
    EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(GrdeclReader, EverySharedSmallFileLoads) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(cutaway::test::shared_data() / "grdecl/small")) {
        if (entry.path().extension() != ".grdecl") continue;
        ++files;
        const CornerPointGrid grid = load_grdecl({entry.path()});
        EXPECT_GT(grid.active_count(), 0u) << entry.path();
    }
    EXPECT_GE(files, 8);
}

TEST(GrdeclReader, IncludeResolvesRelativeToTheIncludingFile) {
    ScratchDir dir("include");
    std::filesystem::create_directories(dir.path() / "sub");
    dir.write("sub/zcorn.inc", "ZCORN\n 8*0 8*1 /\n");
    dir.write("sub/geometry.inc", "INCLUDE\n 'zcorn.inc' /\n");
    const auto main = dir.write("main.grdecl",
                                "SPECGRID\n 2 1 1 /\nCOORD\n 0 0 0 0 0 1 1 0 0 1 0 1 2 0 0 2 0 1\n"
                                " 0 1 0 0 1 1 1 1 0 1 1 1 2 1 0 2 1 1 /\nINCLUDE\n 'sub/geometry.inc' /\n");
    const CornerPointGrid grid = load_grdecl({main});
    EXPECT_EQ(grid.active_count(), 2u);
}

TEST(GrdeclReader, UnknownKeywordsAreSkippedWithAWarningOrKeptAsProperties) {
    GrdeclReader reader;
    reader.read_text(std::string(two_cells) + "FOO\n 1 2 3 /\nMYPROP\n 0.5 0.25 /\nGRID\nBARNUM\n 2*7 /\n", "extra");
    const CornerPointGrid grid = reader.finish();
    ASSERT_EQ(reader.warnings().size(), 2u);
    EXPECT_NE(reader.warnings()[0].find("FOO"), std::string::npos);
    EXPECT_NE(reader.warnings()[0].find("extra:"), std::string::npos);
    ASSERT_NE(grid.property("MYPROP"), nullptr);
    EXPECT_FLOAT_EQ((*grid.property("MYPROP"))[1], 0.25f);
    ASSERT_NE(grid.int_property("BARNUM"), nullptr);
    EXPECT_EQ((*grid.int_property("BARNUM"))[0], 7);
}

TEST(GrdeclReader, RepeatedSolutionKeywordsBecomeTimeSteps) {
    GrdeclReader reader;
    reader.read_text(std::string(two_cells) + "SWAT\n 0.1 0.2 /\nSWAT\n 0.3 0.4 /\nSWAT\n 2*1 /\n", "steps");
    const CornerPointGrid grid = reader.finish();
    ASSERT_EQ(grid.step_count("SWAT"), 3u);
    EXPECT_FLOAT_EQ((*grid.dynamic_property("SWAT", 1))[0], 0.3f);
    EXPECT_EQ(grid.dynamic_property("SWAT", 3), nullptr);
}

TEST(GrdeclReader, FortranDoubleExponentsAreNumbers) {
    GrdeclReader reader;
    reader.read_text(std::string(two_cells) + "PORO\n 2.5D-01 1.0d-1 /\n", "fortran");
    const CornerPointGrid grid = reader.finish();
    EXPECT_FLOAT_EQ((*grid.property("PORO"))[0], 0.25f);
}
