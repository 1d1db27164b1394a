// The OPM Flow deck of a generated model, without running flow: wells stand in active cells on
// opposite flanks (injectors down-dip), the schedule injects the planned pore volumes, and the
// deck text holds what flow needs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>
#include <utility>

#include "generator_test_support.h"
#include "generators/flow_deck_writer.h"
#include "generators/flow_fluid_model.h"
#include "grid/box_grid.h"

namespace cutaway::generators {
namespace {

/// Position of a well's column along the placement's down-dip direction, metres.
double along_dip(const WellPlacement& p, const DeckWell& w) { return w.column.x * p.down_dip_x + w.column.y * p.down_dip_y; }

/// 20 x 12 x 3 cells of 100 x 100 x 10 m; the east half (i >= 10) thrown 40 m down, so the top
/// deepens eastwards; PERMX rises with j (mD), PORO 0.2, NTG 0.5.
grid::CornerPointGrid faulted_box() {
    grid::BoxGridSpec spec;
    spec.dims = {20, 12, 3};
    spec.cell_size = {100, 100, 10};
    spec.fault_i = 10;
    spec.fault_throw = 40;
    grid::CornerPointGrid grid = grid::make_box_grid(spec);
    std::vector<float> permx(grid.cell_count());
    for (std::size_t c = 0; c < permx.size(); ++c) permx[c] = 100.0f + float(grid::cell_ijk(spec.dims, c).j);
    grid.set_property("PERMX", std::move(permx));
    grid.set_property("PORO", std::vector<float>(grid.cell_count(), 0.2f));
    grid.set_property("NTG", std::vector<float>(grid.cell_count(), 0.5f));
    return grid;
}

void expect_wells_in_active_cells(const grid::CornerPointGrid& grid, const std::vector<DeckWell>& wells) {
    for (const DeckWell& w : wells) {
        ASSERT_FALSE(w.column.layers.empty()) << w.name;
        for (int k : w.column.layers)
            EXPECT_TRUE(grid.active(grid.dims().cell_index(w.column.i, w.column.j, k)))
                << w.name << " completed in inactive cell " << w.column.i << ' ' << w.column.j << ' ' << k;
    }
}

TEST(FlowWellPlacement, GeneratedModelWellsOnOppositeFlanksInActiveCells) {
    const GeneratedModel model = testing::generate_quietly(testing::small_parameters());
    const WellPlacement p = place_wells(model.grid);
    ASSERT_FALSE(p.injectors.empty());
    ASSERT_FALSE(p.producers.empty());
    expect_wells_in_active_cells(model.grid, p.injectors);
    expect_wells_in_active_cells(model.grid, p.producers);

    std::set<std::pair<int, int>> columns;
    for (const auto* wells : {&p.injectors, &p.producers})
        for (const DeckWell& w : *wells)
            EXPECT_TRUE(columns.insert({w.column.i, w.column.j}).second) << w.name << " shares its column";

    // Every injector lies further down-dip than every producer.
    double nearest_injector = std::numeric_limits<double>::infinity(), furthest_producer = -nearest_injector;
    for (const DeckWell& w : p.injectors) nearest_injector = std::min(nearest_injector, along_dip(p, w));
    for (const DeckWell& w : p.producers) furthest_producer = std::max(furthest_producer, along_dip(p, w));
    EXPECT_GT(nearest_injector, furthest_producer);
    // 2,400 m by 3,000 m: the flanks are the outer 15% along the dip, so their wells stand at
    // least about 70% of the shorter side apart.
    EXPECT_GT(p.flank_distance, 0.5 * 2400);
}

TEST(FlowWellPlacement, InjectorsOnTheDownthrownSideInTheBestColumns) {
    const grid::CornerPointGrid grid = faulted_box();
    const WellPlacement p = place_wells(grid);
    EXPECT_NEAR(p.down_dip_x, 1, 1e-9);  // the fitted top deepens east; symmetric in y
    EXPECT_NEAR(p.down_dip_y, 0, 1e-9);
    ASSERT_EQ(p.injectors.size(), 1u);  // 1,100 m of strike: one well per flank
    ASSERT_EQ(p.producers.size(), 1u);
    // Flanks are the outer 15% of the 1,900 m between column centres (3 columns each side), less
    // the grid's boundary columns; a flank's one well comes from the middle 60% of the strike
    // (y 270..930 m: j 3..8), where j = 8 has the highest k h.
    EXPECT_TRUE(p.injectors[0].column.i >= 17 && p.injectors[0].column.i <= 18) << p.injectors[0].column.i;
    EXPECT_TRUE(p.producers[0].column.i >= 1 && p.producers[0].column.i <= 2) << p.producers[0].column.i;
    EXPECT_EQ(p.injectors[0].column.j, 8);
    EXPECT_EQ(p.producers[0].column.j, 8);
    EXPECT_EQ(p.injectors[0].column.layers, (std::vector<int>{0, 1, 2}));
}

TEST(FlowWellPlacement, RefusesAModelWithOneActiveColumn) {
    grid::BoxGridSpec spec;
    spec.dims = {1, 1, 4};
    grid::CornerPointGrid grid = grid::make_box_grid(spec);
    grid.set_property("PERMX", std::vector<float>(4, 100.0f));
    grid.set_property("NTG", std::vector<float>(4, 1.0f));
    EXPECT_THROW(place_wells(grid), std::invalid_argument);
}

TEST(FlowSchedule, InjectsThePlannedPoreVolumes) {
    const grid::CornerPointGrid grid = faulted_box();
    const FlowDeckPlan plan = plan_flow_deck(grid);
    const FlowSchedule& s = plan.schedule;
    // 720 cells of 1e5 m3 at PORO 0.2 and NTG 0.5; the cell volumes are exact for a box, so only
    // rounding of the float properties remains.
    EXPECT_NEAR(s.pore_volume_m3, 720 * 1e5 * 0.1, 1e-6 * s.pore_volume_m3);
    const double rate = std::accumulate(s.injection_rate_sm3_day.begin(), s.injection_rate_sm3_day.end(), 0.0);
    const double injected = rate * flow_fluids::water_formation_factor * s.report_steps * s.report_step_days;
    EXPECT_NEAR(injected / s.pore_volume_m3, kInjectedPoreVolumes, 1e-12);
    EXPECT_EQ(s.report_steps, kDeckReportSteps);
    // The planned rate stays within the share of the estimated capacity (steps are whole days).
    EXPECT_LE(rate * flow_fluids::water_formation_factor, kCapacityShare * s.estimated_capacity_m3_day * (1 + 1e-12));
    // Shallowest cell centre: 5 m below the 1,000 m top; the contact below the deepest corner (1,070 m).
    EXPECT_DOUBLE_EQ(s.datum_depth_m, 1005);
    EXPECT_GT(s.water_contact_depth_m, 1070);
    ASSERT_EQ(s.producer_bhp_bar.size(), 1u);
    EXPECT_LT(s.producer_bhp_bar[0], s.datum_pressure_bar);
    EXPECT_GT(s.injector_bhp_limit_bar[0], s.datum_pressure_bar);
}

TEST(FlowDeckText, HoldsTheSectionsWellsAndEveryReportStep) {
    const grid::CornerPointGrid grid = faulted_box();
    const FlowDeckPlan plan = plan_flow_deck(grid);
    const std::string text = flow_deck_text(grid.dims(), plan, "BOX.GRDECL", {"made by a test"});
    for (const char* keyword : {"RUNSPEC", "DIMENS\n  20 12 3 /", "OIL\nWATER", "METRIC", "UNIFOUT", "GRID", "INIT",
                                "INCLUDE\n  'BOX.GRDECL' /", "PROPS", "SWOF", "PVTW", "PVCDO", "DENSITY", "ROCK",
                                "SOLUTION", "EQUIL", "SCHEDULE", "RPTRST\n  'BASIC=2' /", "WCONINJE", "WCONPROD",
                                "END", "-- made by a test"})
        EXPECT_NE(text.find(keyword), std::string::npos) << keyword;
    EXPECT_NE(text.find("TSTEP\n-- 30 report steps of " + std::to_string(plan.schedule.report_step_days) + " days\n  30*"),
              std::string::npos);
    // One COMPDAT line per well here: every column is active from k = 1 to 3.
    const DeckWell& injector = plan.wells.injectors[0];
    EXPECT_NE(text.find("'INJ1' " + std::to_string(injector.column.i + 1) + ' ' + std::to_string(injector.column.j + 1) +
                        " 1 3 'OPEN'"),
              std::string::npos);
}

TEST(FlowDeckFiles, GridFileHoldsOnlyWhatFlowReads) {
    const GeneratedModel model = testing::generate_quietly(testing::small_parameters());
    const std::filesystem::path directory =
        std::filesystem::temp_directory_path() / ("cutaway_flow_deck_files_" + std::to_string(::getpid()));
    std::filesystem::remove_all(directory);
    const FlowDeckFiles files = flow_deck_files(directory, "SMALL");
    write_flow_deck(files, model.grid, plan_flow_deck(model.grid), {});
    std::ostringstream grid_text;
    grid_text << std::ifstream(files.grid).rdbuf();
    const std::string text = grid_text.str();
    for (const char* keyword : {"SPECGRID", "COORD", "ZCORN", "ACTNUM", "PORO", "PERMX", "NTG"})
        EXPECT_NE(text.find(std::string(keyword) + '\n'), std::string::npos) << keyword;
    // FACIES is no Eclipse keyword and SWAT belongs to SOLUTION, not GRID: flow would stop at either.
    for (const char* keyword : {"FACIES", "SWAT"}) EXPECT_EQ(text.find(std::string(keyword) + '\n'), std::string::npos) << keyword;
    EXPECT_TRUE(std::filesystem::exists(files.data));
    std::filesystem::remove_all(directory);
}

}  // namespace
}  // namespace cutaway::generators
