#include <gtest/gtest.h>

#include <sstream>

#include "grid/box_grid.h"
#include "grid/grdecl_reader.h"
#include "grid/grdecl_writer.h"
#include "test_files.h"

using namespace cutaway::grid;

namespace {

CornerPointGrid reread(const CornerPointGrid& grid) {
    std::ostringstream text;
    write_grdecl(text, grid, {{"written by grdecl_roundtrip_test"}});
    GrdeclReader reader;
    reader.read_text(text.str(), "roundtrip");
    return reader.finish();
}

// Bit-identical arrays: the writer prints shortest round-trip text, so no tolerance at all.
void expect_identical(const CornerPointGrid& a, const CornerPointGrid& b) {
    ASSERT_EQ(a.dims(), b.dims());
    EXPECT_EQ(a.coord(), b.coord());
    for (std::size_t n = 0; n < a.dims().zcorn_value_count(); ++n)
        ASSERT_EQ(a.zcorn().value(n), b.zcorn().value(n)) << "ZCORN value " << n;
    EXPECT_EQ(a.actnum(), b.actnum());
    EXPECT_EQ(a.property_names(), b.property_names());
    for (const auto& name : a.property_names()) EXPECT_EQ(*a.property(name), *b.property(name)) << name;
    EXPECT_EQ(a.int_property_names(), b.int_property_names());
    for (const auto& name : a.int_property_names()) EXPECT_EQ(*a.int_property(name), *b.int_property(name)) << name;
    EXPECT_EQ(a.dynamic_property_names(), b.dynamic_property_names());
    for (const auto& name : a.dynamic_property_names()) {
        ASSERT_EQ(a.step_count(name), b.step_count(name));
        for (std::size_t t = 0; t < a.step_count(name); ++t)
            EXPECT_EQ(*a.dynamic_property(name, t), *b.dynamic_property(name, t));
    }
    EXPECT_EQ(a.metadata().mapaxes, b.metadata().mapaxes);
    EXPECT_EQ(a.metadata().grid_unit, b.metadata().grid_unit);
    EXPECT_EQ(a.metadata().map_units, b.metadata().map_units);
    EXPECT_EQ(a.metadata().gdorient, b.metadata().gdorient);
}

}  // namespace

TEST(GrdeclRoundTrip, ReekReadWriteReadIsIdentical) {
    const CornerPointGrid grid = load_grdecl({cutaway::test::reek_grid(), cutaway::test::reek_poro()});
    expect_identical(grid, reread(grid));
}

TEST(GrdeclRoundTrip, EverySmallFileReadWriteReadIsIdentical) {
    for (const auto& entry : std::filesystem::directory_iterator(cutaway::test::shared_data() / "grdecl/small")) {
        if (entry.path().extension() != ".grdecl") continue;
        SCOPED_TRACE(entry.path().string());
        const CornerPointGrid grid = load_grdecl({entry.path()});
        expect_identical(grid, reread(grid));
    }
}

TEST(GrdeclRoundTrip, PropertiesStepsAndGapsSurvive) {
    BoxGridSpec spec;
    spec.dims = {3, 2, 2};
    const CornerPointGrid box = make_box_grid(spec);
    std::vector<double> zcorn;
    for (std::size_t n = 0; n < box.dims().zcorn_value_count(); ++n) zcorn.push_back(box.zcorn().value(n));
    zcorn[2 * 24 + 5] += 0.125;  // a gap between layers forces the full ZCORN layout
    CornerPointGrid grid(box.dims(), box.coord(), ZcornStore::from_values(box.dims(), zcorn),
                         {1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 0, 1});
    grid.set_property("PORO", std::vector<float>(12, 0.1f));
    grid.set_int_property("FACIES", {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
    grid.add_dynamic_step("SWAT", std::vector<float>(12, 0.2f));
    grid.add_dynamic_step("SWAT", std::vector<float>(12, 1.0f / 3.0f));
    grid.metadata().mapaxes = std::array<double, 6>{0, 1, 0, 0, 1, 0};
    ASSERT_FALSE(grid.zcorn().is_compact());
    const CornerPointGrid back = reread(grid);
    EXPECT_FALSE(back.zcorn().is_compact());
    expect_identical(grid, back);
}
