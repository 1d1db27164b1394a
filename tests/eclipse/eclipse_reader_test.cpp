// Simulator output read through src/eclipse/ against opm-common itself, on files OPM Flow wrote
// at test time (the eclipse_flow fixture runs SPE1 and SPE9): the EGRID grid against OPM's
// EclipseGrid built from the same file, INIT and UNRST values against EclIO's own reads (mapped
// to cells by EclIO's EGrid::active_index, not by our ACTNUM spreading), step dates against the
// decks' schedules, and every refusal of bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <opm/input/eclipse/EclipseState/Grid/EclipseGrid.hpp>
#include <opm/io/eclipse/EGrid.hpp>
#include <opm/io/eclipse/EInit.hpp>
#include <opm/io/eclipse/ERst.hpp>

#include "eclipse/case_files.h"
#include "eclipse/eclipse_error.h"
#include "eclipse/egrid_reader.h"
#include "eclipse/init_reader.h"
#include "eclipse/report_steps.h"
#include "eclipse/simulator_case.h"
#include "grid/cell_geometry.h"

namespace cutaway::eclipse {
namespace {

namespace fs = std::filesystem;

const fs::path flow_cases = CUTAWAY_FLOW_CASES;
const fs::path spe1 = flow_cases / "spe1" / "SPE1CASE2";
const fs::path spe9 = flow_cases / "spe9" / "SPE9";
constexpr std::size_t memory_limit = std::size_t(1) << 30;

fs::path with_extension(const fs::path& stem, const std::string& extension) { return fs::path(stem.string() + extension); }

/// A scratch folder per test, emptied first.
fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / ("eclipse_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void copy_bytes(const fs::path& from, const fs::path& to, std::size_t count = std::size_t(-1)) {
    std::ifstream in(from, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes.resize(std::min(bytes.size(), count));
    std::ofstream(to, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

/// What `read` throws as an EclipseError (a failure when it throws nothing or something else).
template <typename Read>
std::string eclipse_error_of(Read&& read) {
    try {
        read();
    } catch (const EclipseError& error) {
        return error.what();
    } catch (const std::exception& error) {
        return std::string("not an EclipseError: ") + error.what();
    }
    return "nothing thrown";
}

// ---------------------------------------------------------------------------------------------
// The grid against OPM's EclipseGrid from the same EGRID.

class FlowCase : public testing::TestWithParam<fs::path> {};

TEST_P(FlowCase, EgridEqualsOpmEclipseGrid) {
    const fs::path egrid = with_extension(GetParam(), ".EGRID");
    const grid::CornerPointGrid ours = read_egrid(egrid, memory_limit);
    const Opm::EclipseGrid opm(egrid.string());
    // OPM's EclipseGrid works in SI units: a FIELD case's feet (GRIDUNIT FEET, as SPE1 and SPE9
    // write) come back as metres, while we keep the file's units as the GRDECL reader does.
    ASSERT_TRUE(ours.metadata().grid_unit == "FEET" || ours.metadata().grid_unit == "METRES") << ours.metadata().grid_unit;
    const double metres = ours.metadata().grid_unit == "FEET" ? 0.3048 : 1.0;
    const grid::GridDims& d = ours.dims();
    ASSERT_EQ(std::size_t(d.nx), opm.getNX());
    ASSERT_EQ(std::size_t(d.ny), opm.getNY());
    ASSERT_EQ(std::size_t(d.nz), opm.getNZ());
    ASSERT_EQ(ours.active_count(), opm.getNumActive());
    // Volumes relative to OPM's own; centres relative to the active cells' bounding-box diagonal
    // (a centre near the origin has no scale of its own). 1e-6, as the GRDECL reference test: EGRID
    // holds float COORD and ZCORN which both sides widen to double identically, so only the order
    // of operations (OPM's calculateCellVol against our trilinear volume) and OPM's feet-to-metres
    // scaling differ, rounding errors orders of magnitude below it; a misread corner moves far more.
    for (std::size_t cell = 0; cell < ours.cell_count(); ++cell)
        ASSERT_EQ(ours.active(cell), opm.cellActive(cell)) << "cell " << cell;
    const grid::Box3 bounds = grid::grid_bounds(ours);
    const double diagonal =
        metres * std::hypot(bounds.max.x - bounds.min.x, bounds.max.y - bounds.min.y, bounds.max.z - bounds.min.z);
    ASSERT_GT(diagonal, 0);
    double worst_volume = 0, worst_centre = 0;
    for (std::size_t cell = 0; cell < ours.cell_count(); ++cell) {
        if (!ours.active(cell)) continue;
        const grid::CellIjk ijk = grid::cell_ijk(d, cell);
        const grid::CellCorners corners = grid::cell_corners(ours, ijk.i, ijk.j, ijk.k);
        const double opm_volume = opm.getCellVolume(cell);
        const double volume = grid::cell_volume(corners) * metres * metres * metres;
        worst_volume = std::max(worst_volume, std::abs(volume - opm_volume) / opm_volume);
        const grid::Point3 c = grid::cell_centre(corners);
        const auto oc = opm.getCellCenter(cell);
        worst_centre = std::max({worst_centre, std::abs(metres * c.x - oc[0]) / diagonal,
                                 std::abs(metres * c.y - oc[1]) / diagonal, std::abs(metres * c.z - oc[2]) / diagonal});
    }
    EXPECT_LE(worst_volume, 1e-6);
    EXPECT_LE(worst_centre, 1e-6);
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", worst_volume);
    RecordProperty("max_volume_rel_diff", text);
    std::snprintf(text, sizeof text, "%.3g", worst_centre);
    RecordProperty("max_centre_diff_over_diagonal", text);
}

/// Array `name` of `step` per cell as EclIO reads it, placed by EclIO's EGrid::active_index.
std::vector<float> eclio_restart_cells(const fs::path& stem, const std::string& name, int report_number) {
    Opm::EclIO::EGrid egrid(with_extension(stem, ".EGRID").string());
    Opm::EclIO::ERst rst(with_extension(stem, ".UNRST").string());
    const std::vector<float>& active = rst.getRestartData<float>(name, report_number);
    const std::array<int, 3>& n = egrid.dimension();
    std::vector<float> cells(std::size_t(egrid.totalNumberOfCells()), 0.0f);
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i)
                if (const int a = egrid.active_index(i, j, k); a >= 0)
                    cells[std::size_t(egrid.global_index(i, j, k))] = active.at(std::size_t(a));
    return cells;
}

TEST_P(FlowCase, RestartValuesEqualEclio) {
    const grid::CornerPointGrid grid = read_egrid(with_extension(GetParam(), ".EGRID"), memory_limit);
    const ReportSteps steps(with_extension(GetParam(), ".UNRST"), grid, memory_limit);
    ASSERT_GE(steps.step_count(), 3u);
    for (const std::size_t index : {std::size_t(0), steps.step_count() / 2, steps.step_count() - 1})
        for (const std::string name : {"SWAT", "SGAS", "PRESSURE"}) {
            ASSERT_TRUE(steps.has_property(name)) << name;
            EXPECT_EQ(steps.values(name, index), eclio_restart_cells(GetParam(), name, steps.steps()[index].report_number))
                << name << " at step " << index;
        }
}

TEST_P(FlowCase, SoilIsOneMinusSwatMinusSgasWhereTheFileHasNone) {
    const grid::CornerPointGrid grid = read_egrid(with_extension(GetParam(), ".EGRID"), memory_limit);
    const ReportSteps steps(with_extension(GetParam(), ".UNRST"), grid, memory_limit);
    Opm::EclIO::ERst rst(with_extension(GetParam(), ".UNRST").string());
    const int last = steps.steps().back().report_number;
    ASSERT_FALSE(rst.hasArray("SOIL", last)) << "flow wrote SOIL: nothing to derive";
    ASSERT_TRUE(steps.soil_derived());
    const std::vector<float> soil = steps.values("SOIL", steps.step_count() - 1);
    const std::vector<float> swat = eclio_restart_cells(GetParam(), "SWAT", last);
    const std::vector<float> sgas = eclio_restart_cells(GetParam(), "SGAS", last);
    bool some_oil = false;
    for (std::size_t cell = 0; cell < soil.size(); ++cell) {
        if (!grid.active(cell)) continue;
        EXPECT_EQ(soil[cell], 1.0f - swat[cell] - sgas[cell]) << "cell " << cell;  // the same float expression
        some_oil = some_oil || soil[cell] > 0.1f;
    }
    EXPECT_TRUE(some_oil);
}

INSTANTIATE_TEST_SUITE_P(Flow, FlowCase, testing::Values(spe1, spe9),
                         [](const testing::TestParamInfo<fs::path>& info) { return info.param.filename().string(); });

// ---------------------------------------------------------------------------------------------
// SPE1: INIT arrays, steps and dates.

TEST(Spe1, InitArraysEqualEclio) {
    const SimulatorCase loaded = load_simulator_case(*find_case_files(spe1.string()), memory_limit, std::nullopt);
    Opm::EclIO::EInit init(with_extension(spe1, ".INIT").string());
    Opm::EclIO::EGrid egrid(with_extension(spe1, ".EGRID").string());
    for (const std::string name : {"PORO", "PERMX", "PERMZ", "NTG", "DEPTH"}) {
        const std::vector<float>* ours = loaded.grid.property(name);
        ASSERT_NE(ours, nullptr) << name;
        const std::vector<float>& active = init.getInitData<float>(name);
        for (std::size_t cell = 0; cell < ours->size(); ++cell) {
            const auto ijk = egrid.ijk_from_global_index(int(cell));
            const int a = egrid.active_index(ijk[0], ijk[1], ijk[2]);
            EXPECT_EQ((*ours)[cell], a >= 0 ? active[std::size_t(a)] : 0.0f) << name << " cell " << cell;
        }
    }
    const std::vector<std::int32_t>* satnum = loaded.grid.int_property("SATNUM");
    ASSERT_NE(satnum, nullptr);
    EXPECT_EQ(std::vector<int>(satnum->begin(), satnum->end()), init.getInitData<int>("SATNUM"));  // all 300 active
}

TEST(Spe1, LoadingOnePropertyReadsOnlyThatInitArray) {
    const SimulatorCase loaded = load_simulator_case(*find_case_files(spe1.string()), memory_limit, std::string("PERMX"));
    EXPECT_EQ(loaded.grid.property_names(), std::vector<std::string>{"PERMX"});
    EXPECT_TRUE(loaded.grid.int_property_names().empty());
}

TEST(Spe1, ReportStepsFollowTheScheduleFromTheStartDate) {
    // SPE1CASE2.DATA: START 1 JAN 2015; TSTEP 31 28 31 30 31 30 31 31 30 31 30 31 ten times (120
    // reports, February always 28 days); RPTRST BASIC=1: a restart at every report from report 1.
    const grid::CornerPointGrid grid = read_egrid(with_extension(spe1, ".EGRID"), memory_limit);
    const ReportSteps steps(with_extension(spe1, ".UNRST"), grid, memory_limit);
    Opm::EclIO::ERst rst(with_extension(spe1, ".UNRST").string());
    ASSERT_EQ(steps.step_count(), rst.numberOfReportSteps());
    ASSERT_EQ(steps.step_count(), 120u);
    const int month_days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    using namespace std::chrono;
    const sys_days start = year{2015} / January / 1;
    int elapsed = 0;
    for (const ReportStep& step : steps.steps()) {
        EXPECT_EQ(step.report_number, int(step.index) + 1);
        elapsed += month_days[step.index % 12];
        const year_month_day date(start + days(elapsed));
        EXPECT_EQ(step.year, int(date.year())) << "step " << step.index;
        EXPECT_EQ(step.month, int(unsigned(date.month()))) << "step " << step.index;
        EXPECT_EQ(step.day, int(unsigned(date.day()))) << "step " << step.index;
        EXPECT_DOUBLE_EQ(step.elapsed_days, double(elapsed)) << "step " << step.index;
    }
    EXPECT_EQ(steps.steps().front().date(), "2015-02-01");
    const auto wells = steps.steps().back().wells;
    ASSERT_EQ(wells.size(), 2u);  // SPE1CASE2's WELSPECS: PROD, then INJ (gas), both open
    EXPECT_EQ(wells[0].name, "PROD");
    EXPECT_EQ(wells[0].type, "producer");
    EXPECT_EQ(wells[1].name, "INJ");
    EXPECT_EQ(wells[1].type, "gas_injector");
    for (const WellAtStep& well : wells) EXPECT_EQ(well.status, "open") << well.name;
}

TEST(Spe9, TwentySixWellsAtEveryStep) {
    const grid::CornerPointGrid grid = read_egrid(with_extension(spe9, ".EGRID"), memory_limit);
    const ReportSteps steps(with_extension(spe9, ".UNRST"), grid, memory_limit);
    for (const ReportStep& step : steps.steps()) EXPECT_EQ(step.wells.size(), 26u) << "step " << step.index;
}

// ---------------------------------------------------------------------------------------------
// The case named by a MODEL argument.

TEST(CaseFiles, EgridOrCaseNameFindTheFilesBeside) {
    const auto by_egrid = find_case_files(with_extension(spe1, ".EGRID").string());
    const auto by_name = find_case_files(spe1.string());
    ASSERT_TRUE(by_egrid && by_name);
    EXPECT_EQ(by_egrid->egrid, by_name->egrid);
    EXPECT_EQ(by_name->init, with_extension(spe1, ".INIT"));
    EXPECT_EQ(by_name->unrst, with_extension(spe1, ".UNRST"));
    EXPECT_FALSE(find_case_files(with_extension(spe9, ".DATA").string())) << "a deck is not a case";
    EXPECT_FALSE(find_case_files("preset:petra"));
    const auto spe9_case = find_case_files(spe9.string());
    ASSERT_TRUE(spe9_case);
    EXPECT_FALSE(spe9_case->init) << "SPE9 writes no INIT";
}

TEST(SimulatorCase, DeclaresRestartArraysAndHoldsOneStepAtATime) {
    SimulatorCase loaded = load_simulator_case(*find_case_files(spe1.string()), memory_limit, std::nullopt);
    ASSERT_TRUE(loaded.report_steps);
    const std::size_t count = loaded.report_steps->step_count();
    EXPECT_EQ(loaded.grid.step_count("SWAT"), count);
    EXPECT_EQ(loaded.grid.dynamic_property("SWAT", 0), nullptr) << "nothing held after loading";
    hold_report_step(loaded.grid, *loaded.report_steps, "SWAT", 5);
    ASSERT_NE(loaded.grid.dynamic_property("SWAT", 5), nullptr);
    const std::size_t one_step = loaded.grid.property_bytes();
    hold_report_step(loaded.grid, *loaded.report_steps, "SWAT", 7);
    EXPECT_EQ(loaded.grid.dynamic_property("SWAT", 5), nullptr) << "the step held before is released";
    EXPECT_EQ(*loaded.grid.dynamic_property("SWAT", 7), loaded.report_steps->values("SWAT", 7));
    EXPECT_EQ(loaded.grid.property_bytes(), one_step);
}

// ---------------------------------------------------------------------------------------------
// Bad input: one EclipseError naming the file (and array), never a crash.

TEST(BadInput, MissingTruncatedAndForeignEgrid) {
    const fs::path dir = scratch("bad_egrid");
    EXPECT_NE(eclipse_error_of([&] { read_egrid(dir / "NONE.EGRID", memory_limit); }).find("NONE.EGRID: expected an EGRID file, found no such file"),
              std::string::npos);
    const fs::path egrid = with_extension(spe1, ".EGRID");
    for (const std::size_t keep : {std::size_t(100), fs::file_size(egrid) / 2, fs::file_size(egrid) - 4}) {
        copy_bytes(egrid, dir / "CUT.EGRID", keep);
        const std::string message = eclipse_error_of([&] { read_egrid(dir / "CUT.EGRID", memory_limit); });
        EXPECT_NE(message.find("CUT.EGRID: "), std::string::npos) << keep << " bytes: " << message;
        EXPECT_EQ(message.find(".cpp:"), std::string::npos) << "OPM's source location is dropped: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    copy_bytes(with_extension(spe1, ".INIT"), dir / "INIT_AS.EGRID");
    EXPECT_NE(eclipse_error_of([&] { read_egrid(dir / "INIT_AS.EGRID", memory_limit); })
                  .find("INIT_AS.EGRID: expected an Eclipse binary grid (EGRID with GRIDHEAD, COORD, ZCORN), found no "
                        "GRIDHEAD (first array INTEHEAD)"),
              std::string::npos);
    std::ofstream(dir / "TEXT.EGRID") << "SPECGRID\n 1 1 1 /\n";
    EXPECT_NE(eclipse_error_of([&] { read_egrid(dir / "TEXT.EGRID", memory_limit); }).find("TEXT.EGRID: expected an Eclipse binary grid"),
              std::string::npos);
}

TEST(BadInput, GridBeyondTheMemoryLimit) {
    const std::string message = eclipse_error_of([&] { read_egrid(with_extension(spe1, ".EGRID"), 1000); });
    EXPECT_NE(message.find("SPE1CASE2.EGRID: expected at most 1000 bytes (--memory-limit-gb) to read COORD, ZCORN and ACTNUM, found 39012 bytes needed"), std::string::npos) << message;
}

TEST(BadInput, TruncatedAndForeignRestart) {
    // EclIO lists a file cut short up to its last complete array, so a cut restart reads as a
    // shorter run, or a step lacking arrays, unless too little is left to list. Whatever the cut:
    // an EclipseError naming the file, or steps whose values are the full file's.
    const fs::path dir = scratch("bad_unrst");
    const grid::CornerPointGrid grid = read_egrid(with_extension(spe1, ".EGRID"), memory_limit);
    const fs::path unrst = with_extension(spe1, ".UNRST");
    const ReportSteps full(unrst, grid, memory_limit);
    const std::size_t size = fs::file_size(unrst);
    int refused = 0, shorter = 0;
    for (const std::size_t keep : {std::size_t(50), size / 1000, size / 7, size / 3, size / 2, size - 1000, size - 4}) {
        copy_bytes(unrst, dir / "CUT.UNRST", keep);
        const std::string message = eclipse_error_of([&] {
            const ReportSteps cut(dir / "CUT.UNRST", grid, memory_limit);
            EXPECT_LE(cut.step_count(), full.step_count());
            for (std::size_t step = 0; step < cut.step_count(); ++step) {
                EXPECT_EQ(cut.steps()[step].report_number, full.steps()[step].report_number);
                EXPECT_EQ(cut.values("SWAT", step), full.values("SWAT", step)) << keep << " bytes, step " << step;
            }
            ++shorter;
        });
        if (message == "nothing thrown") continue;
        ++refused;
        EXPECT_NE(message.find("CUT.UNRST: "), std::string::npos) << keep << " bytes: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_GE(refused, 1) << "50 bytes hold no report step";
    EXPECT_GE(shorter, 1);
    copy_bytes(with_extension(spe1, ".EGRID"), dir / "GRID_AS.UNRST");
    EXPECT_NE(eclipse_error_of([&] { ReportSteps(dir / "GRID_AS.UNRST", grid, memory_limit); }).find("GRID_AS.UNRST: "),
              std::string::npos);
}

TEST(BadInput, RestartOfAnotherGrid) {
    const grid::CornerPointGrid grid = read_egrid(with_extension(spe1, ".EGRID"), memory_limit);
    const std::string message = eclipse_error_of([&] { ReportSteps(with_extension(spe9, ".UNRST"), grid, memory_limit); });
    EXPECT_NE(message.find("SPE9.UNRST: array INTEHEAD at report 1: expected a restart of the EGRID's grid: 10 x 10 x 3 "
                           "cells, 300 active, found 24 x 25 x 15 cells, 9000 active"),
              std::string::npos)
        << message;
}

TEST(BadInput, InitOfAnotherGrid) {
    grid::CornerPointGrid grid = read_egrid(with_extension(spe9, ".EGRID"), memory_limit);
    const std::string message =
        eclipse_error_of([&] { add_init_properties(grid, with_extension(spe1, ".INIT"), memory_limit, std::nullopt); });
    EXPECT_NE(message.find("SPE1CASE2.INIT: array INTEHEAD: expected the EGRID's grid: 24 x 25 x 15 cells"), std::string::npos)
        << message;
}

TEST(BadInput, MissingArrayAndStepOutOfRange) {
    const grid::CornerPointGrid grid = read_egrid(with_extension(spe1, ".EGRID"), memory_limit);
    const ReportSteps steps(with_extension(spe1, ".UNRST"), grid, memory_limit);
    EXPECT_NE(eclipse_error_of([&] { steps.values("NOPE", 0); }).find("array NOPE: expected a per-cell restart array"),
              std::string::npos);
    const std::string beyond = eclipse_error_of([&] { steps.values("SWAT", steps.step_count()); });
    EXPECT_NE(beyond.find("array SWAT: expected a report step index 0.." + std::to_string(steps.step_count() - 1)),
              std::string::npos)
        << beyond;
}

TEST(BadInput, StepReadBeyondTheMemoryLimit) {
    const grid::CornerPointGrid grid = read_egrid(with_extension(spe1, ".EGRID"), memory_limit);
    const std::string message = eclipse_error_of([&] { ReportSteps(with_extension(spe1, ".UNRST"), grid, 1000); });
    EXPECT_NE(message.find("SPE1CASE2.UNRST: expected at most 1000 bytes (--memory-limit-gb) to read a report step's arrays"), std::string::npos) << message;
}

}  // namespace
}  // namespace cutaway::eclipse
