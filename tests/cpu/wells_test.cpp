// Wells from decks (opm-common's parser), their paths in model coordinates and the --wells values.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "grid/box_grid.h"
#include "grid/cell_geometry.h"
#include "io/bad_input_error.h"
#include "test_files.h"
#include "wells/deck_wells.h"
#include "wells/well_paths.h"
#include "wells/well_selection.h"

namespace cutaway::wells {
namespace {

const Well& named(const std::vector<Well>& wells, const std::string& name) {
    for (const Well& w : wells)
        if (w.name == name) return w;
    throw std::logic_error("no well " + name);
}

TEST(DeckWells, Spe9HasItsWelspecsWellsWithCompdatConnectionsAndControls) {
    const std::vector<Well> wells = read_deck_wells(test::shared_data() / "opm/spe9/SPE9.DATA");
    ASSERT_EQ(wells.size(), 26u);  // WELSPECS: INJE1, PRODU2 ... PRODU26
    EXPECT_EQ(wells.front().name, "INJE1");
    EXPECT_EQ(wells.back().name, "PRODU26");
    const Well& injector = named(wells, "INJE1");
    EXPECT_EQ(injector.kind, WellKind::injector);
    EXPECT_EQ(injector.injected_phase, "WATER");
    EXPECT_EQ(injector.head_i, 23);  // WELSPECS 24 25, 1-based
    EXPECT_EQ(injector.head_j, 24);
    ASSERT_EQ(injector.connections.size(), 5u);  // COMPDAT K 11..15
    EXPECT_EQ(injector.connections.front().k, 10);
    EXPECT_EQ(injector.connections.back().k, 14);
    for (const Well& w : wells) {
        EXPECT_EQ(w.status, WellStatus::open) << w.name;
        if (w.name == "INJE1") continue;
        // WCONPROD 'PRODU*': every producer through the pattern; COMPDAT K 2..4 in the head's column.
        EXPECT_EQ(w.kind, WellKind::producer) << w.name;
        ASSERT_EQ(w.connections.size(), 3u) << w.name;
        for (const WellConnection& c : w.connections) {
            EXPECT_EQ(c.i, w.head_i);
            EXPECT_EQ(c.j, w.head_j);
            EXPECT_TRUE(c.open);
        }
    }
    EXPECT_EQ(named(wells, "PRODU10").head_i, 10);
    EXPECT_EQ(named(wells, "PRODU10").head_j, 8);
}

TEST(DeckWells, DefaultedOrZeroColumnsAreTheWellheadsAndStatesAreKept) {
    const test::ScratchDir dir("deck-wells-defaults");
    const auto file = dir.write("wells.inc",
                                "WELSPECS\n 'A1' 'G' 3 4 1* 'OIL' /\n 'B2' 'G' 5 6 1* 'WATER' /\n 'C3' 'G' 1 1 1* 'OIL' /\n/\n"
                                "COMPDAT\n 'A1' 1* 1* 1 3 'OPEN' /\n 'B2' 0 0 2 2 'SHUT' /\n 'C3' 2 1 1 1 /\n/\n"
                                "WCONINJH\n 'B2' 'GAS' 'SHUT' /\n/\n");
    const std::vector<Well> wells = read_deck_wells(file);
    ASSERT_EQ(wells.size(), 3u);
    ASSERT_EQ(wells[0].connections.size(), 3u);
    EXPECT_EQ(wells[0].connections[2].i, 2);
    EXPECT_EQ(wells[0].connections[2].j, 3);
    EXPECT_EQ(wells[0].connections[2].k, 2);
    EXPECT_EQ(wells[0].kind, WellKind::unknown);  // no control keyword names it
    ASSERT_EQ(wells[1].connections.size(), 1u);
    EXPECT_EQ(wells[1].connections[0].i, 4);
    EXPECT_FALSE(wells[1].connections[0].open);
    EXPECT_EQ(wells[1].kind, WellKind::injector);
    EXPECT_EQ(wells[1].injected_phase, "GAS");
    EXPECT_EQ(wells[1].status, WellStatus::shut);
    EXPECT_EQ(wells[2].connections[0].i, 1);  // away from its head column (0, 0)
}

TEST(DeckWells, BadDecksAreRefusedNamingTheFile) {
    const test::ScratchDir dir("deck-wells-bad");
    EXPECT_THROW(read_deck_wells(dir.path() / "missing.DATA"), io::BadInputError);
    EXPECT_THROW(read_deck_wells(dir.write("no_wells.inc", "PORO\n 4*0.2 /\n")), io::BadInputError);
    EXPECT_THROW(read_deck_wells(dir.write("malformed.inc", "WELSPECS\n 'W' 'G' abc 4 /\n/\n")), io::BadInputError);
    EXPECT_THROW(read_deck_wells(dir.write("undefined.inc", "WELSPECS\n 'W' 'G' 1 1 /\n/\nCOMPDAT\n 'X' 1 1 1 1 /\n/\n")),
                 io::BadInputError);
    EXPECT_THROW(read_deck_wells(dir.write("layers.inc", "WELSPECS\n 'W' 'G' 1 1 /\n/\nCOMPDAT\n 'W' 1 1 3 2 /\n/\n")),
                 io::BadInputError);
    try {
        read_deck_wells(dir.path() / "malformed.inc");
        FAIL();
    } catch (const io::BadInputError& e) {
        EXPECT_NE(std::string(e.what()).find("malformed.inc"), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    }
}

TEST(WellsWithinGrid, ConnectionsOutsideTheGridAreRefused) {
    const grid::GridDims dims{4, 4, 3};
    Well well{"W", WellKind::producer, "", WellStatus::open, 1, 1, {{1, 1, 0, true}, {1, 1, 2, true}}};
    EXPECT_NO_THROW(check_within_grid({well}, dims, "f"));
    well.connections.push_back({1, 1, 3, true});
    EXPECT_THROW(check_within_grid({well}, dims, "f"), io::BadInputError);
    well.connections.pop_back();
    well.head_i = 4;
    EXPECT_THROW(check_within_grid({well}, dims, "f"), io::BadInputError);
}

grid::CornerPointGrid box_grid() {
    grid::BoxGridSpec spec;
    spec.dims = {5, 4, 3};
    spec.cell_size = {100, 50, 10};
    spec.origin = {1000, 2000, 3000};
    return grid::make_box_grid(spec);
}

TEST(WellPaths, FromAboveTheModelThroughTheConnectedCellCentres) {
    const grid::CornerPointGrid grid = box_grid();
    const WellheadLevel level = wellhead_level(grid);
    EXPECT_DOUBLE_EQ(level.top, 3000);
    EXPECT_DOUBLE_EQ(level.head, 3000 - 0.25 * 30);  // a quarter of the 30 m thickness above the top
    const Well vertical{"V", WellKind::producer, "", WellStatus::open, 2, 1, {{2, 1, 0, true}, {2, 1, 2, true}}};
    const std::vector<grid::Point3> path = well_path(vertical, grid, level);
    ASSERT_EQ(path.size(), 3u);
    EXPECT_DOUBLE_EQ(path[0].x, 1000 + 2.5 * 100);
    EXPECT_DOUBLE_EQ(path[0].y, 2000 + 1.5 * 50);
    EXPECT_DOUBLE_EQ(path[0].z, level.head);
    EXPECT_DOUBLE_EQ(path[1].z, 3005);  // layer 0's centre
    EXPECT_DOUBLE_EQ(path[2].z, 3025);  // layer 2's centre
    // A deviated well: straight down in the head's column to the first connection's depth, then across.
    const Well deviated{"D", WellKind::injector, "WATER", WellStatus::open, 0, 0, {{3, 0, 1, true}, {4, 0, 1, true}}};
    const std::vector<grid::Point3> bend = well_path(deviated, grid, level);
    ASSERT_EQ(bend.size(), 4u);
    EXPECT_DOUBLE_EQ(bend[1].x, bend[0].x);
    EXPECT_DOUBLE_EQ(bend[1].z, 3015);
    EXPECT_DOUBLE_EQ(bend[2].x, 1000 + 3.5 * 100);
    // No connection: the wellhead down to the model's top.
    const std::vector<grid::Point3> stub = well_path({"S", WellKind::unknown, "", WellStatus::open, 4, 3, {}}, grid, level);
    ASSERT_EQ(stub.size(), 2u);
    EXPECT_DOUBLE_EQ(stub[1].z, 3000);
    const WellPathMap paths = well_paths({vertical, deviated}, grid);
    EXPECT_TRUE(find_well_path(paths, "D"));
    EXPECT_FALSE(find_well_path(paths, "X"));
}

TEST(WellPaths, DefaultRadiusIsAFifthOfTheNarrowerCellWidth) {
    // Columns 100 x 50 m: a fifth of 50; the 0.3% of the 539 m diagonal floor is below that.
    EXPECT_DOUBLE_EQ(default_well_radius(box_grid()), 10.0);
}

TEST(WellsOption, FilesSelectionsAndUnknownNames) {
    EXPECT_FALSE(parse_wells_option({}).draws());
    EXPECT_FALSE(parse_wells_option({"none"}).draws());
    EXPECT_TRUE(parse_wells_option({"all"}).draws());
    const WellsOption file_only = parse_wells_option({"dir/WELLS.inc"});
    ASSERT_TRUE(file_only.file);
    EXPECT_TRUE(file_only.draws());
    EXPECT_TRUE(names_a_file("CASE.DATA"));
    EXPECT_FALSE(names_a_file("PRODU2"));
    const WellsOption named_option = parse_wells_option({"x.grdecl", "B,A"});
    ASSERT_EQ(named_option.names.size(), 2u);
    EXPECT_THROW(parse_wells_option({"a.DATA", "b.DATA"}), std::invalid_argument);
    EXPECT_THROW(parse_wells_option({"all", "none"}), std::invalid_argument);
    EXPECT_THROW(parse_wells_option({"A,,B"}), std::invalid_argument);
    const std::vector<Well> wells{{"A", WellKind::producer, "", WellStatus::open, 0, 0, {}},
                                  {"B", WellKind::producer, "", WellStatus::open, 0, 0, {}},
                                  {"C", WellKind::producer, "", WellStatus::open, 0, 0, {}}};
    const std::vector<Well> picked = select_wells(wells, named_option, "x.grdecl");
    ASSERT_EQ(picked.size(), 2u);
    EXPECT_EQ(picked[0].name, "A");  // the wells' order, not the option's
    try {
        select_wells(wells, parse_wells_option({"NOPE"}), "x.grdecl");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("A, B, C"), std::string::npos) << "lists the known wells: " << e.what();
    }
}

}  // namespace
}  // namespace cutaway::wells
