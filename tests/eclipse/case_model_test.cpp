// A simulator case as a MODEL argument (app_core/model_source.h) on OPM Flow's SPE1 and SPE9 output
// (the eclipse_flow fixture): what load_model reads, what hold_property adds or releases, the
// MPI path's box, and that reading step after step holds one step.
#include <gtest/gtest.h>

#include <malloc.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "app_core/model_source.h"
#include "eclipse/report_steps.h"
#include "grid/grid_box.h"

namespace cutaway::app {
namespace {

namespace fs = std::filesystem;

const fs::path flow_cases = CUTAWAY_FLOW_CASES;
const std::string spe1 = (flow_cases / "spe1" / "SPE1CASE2").string();
const std::string spe9 = (flow_cases / "spe9" / "SPE9").string();
constexpr std::size_t memory_limit = std::size_t(1) << 30;

TEST(CaseModel, LoadsTheGridInitArraysAndDeclaresTheStepsWithoutReadingThem) {
    const LoadedModel model = load_model({spe1 + ".EGRID"}, memory_limit);
    ASSERT_TRUE(model.report_steps);
    EXPECT_NE(model.description.find("SPE1CASE2.EGRID + SPE1CASE2.INIT + SPE1CASE2.UNRST (120 report steps)"),
              std::string::npos)
        << model.description;
    EXPECT_NE(model.grid.property("PORO"), nullptr);
    EXPECT_NE(model.grid.int_property("SATNUM"), nullptr);
    for (const std::string name : {"PRESSURE", "RS", "SGAS", "SOIL", "SWAT"}) {
        EXPECT_EQ(model.grid.step_count(name), 120u) << name;
        EXPECT_EQ(model.grid.dynamic_property(name, 0), nullptr) << name;
    }
    EXPECT_EQ(default_property_name(model.grid), "PORO");
    EXPECT_EQ(model.grid.metadata().unit_system, "FIELD");  // SPE1CASE2.DATA's RUNSPEC: FIELD
    EXPECT_EQ(model.grid.metadata().grid_unit, "FEET");
    EXPECT_EQ(model_dims({spe9}, memory_limit), (grid::GridDims{24, 25, 15}));
}

TEST(CaseModel, HoldPropertyReadsAnInitArrayOrOneReportStep) {
    LoadedModel model = load_model({spe1}, memory_limit, std::string("SWAT"));
    EXPECT_TRUE(model.grid.property_names().empty()) << "only the INIT array asked for is read";
    hold_property(model, "PERMX", -1, memory_limit);
    EXPECT_NE(model.grid.property("PERMX"), nullptr);
    EXPECT_FALSE(holds_time_step(model, "SWAT", 5));
    hold_property(model, "SWAT", 5, memory_limit);
    EXPECT_TRUE(holds_time_step(model, "SWAT", 5));
    ASSERT_NE(model.grid.dynamic_property("SWAT", 5), nullptr);
    EXPECT_EQ(*model.grid.dynamic_property("SWAT", 5), model.report_steps->values("SWAT", 5));
    hold_property(model, "SWAT", 6, memory_limit);
    EXPECT_EQ(model.grid.dynamic_property("SWAT", 5), nullptr) << "one step per array";
    try {
        hold_property(model, "SWAT", 120, memory_limit);
        FAIL() << "step 120 of 120 accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("--time-step 120: expected a report step 0..119 of "), std::string::npos)
            << error.what();
    }
    EXPECT_NE(model.grid.dynamic_property("SWAT", 6), nullptr) << "a refused step releases nothing";
}

TEST(CaseModel, ACaseTakesNoFurtherFiles) {
    for (const std::vector<std::string>& model : {std::vector<std::string>{spe1 + ".EGRID", spe9 + ".DATA"},
                                                  std::vector<std::string>{spe9 + ".DATA", spe1 + ".EGRID"}})
        try {
            load_model(model, memory_limit);
            FAIL() << "accepted a case with a further file";
        } catch (const std::invalid_argument& error) {
            EXPECT_NE(std::string(error.what()).find("SPE1CASE2.EGRID: a simulator case takes no further files"),
                      std::string::npos)
                << error.what();
        }
}

TEST(CaseModel, WithoutInitTheDefaultPropertyIsTheFirstRestartArray) {
    LoadedModel model = load_model({spe9}, memory_limit, std::string());
    EXPECT_FALSE(model.init_file);
    EXPECT_EQ(default_property_name(model.grid), "PRESSURE");
    EXPECT_EQ(model.grid.metadata().unit_system, "FIELD") << "from the restart's INTEHEAD without an INIT";
    hold_property(model, "", -1, memory_limit);
    EXPECT_NE(model.grid.dynamic_property("PRESSURE", 0), nullptr);
}

TEST(CaseModel, BlockEqualsTheBoxOfTheWholeCaseAtTheStep) {
    const grid::IjkBox box{3, 4, 5, 20, 10, 14};
    const LoadedModel block = load_block({spe9}, box, memory_limit, "SWAT", 40);
    LoadedModel whole = load_model({spe9}, memory_limit, std::string("SWAT"));
    hold_property(whole, "SWAT", 40, memory_limit);
    const grid::CornerPointGrid expected = grid::extract_box(whole.grid, box);
    EXPECT_EQ(block.grid.dims(), expected.dims());
    EXPECT_EQ(block.grid.coord(), expected.coord());
    EXPECT_EQ(block.grid.actnum(), expected.actnum());
    for (std::size_t v = 0; v < expected.dims().zcorn_value_count(); ++v)
        ASSERT_EQ(block.grid.zcorn().value(v), expected.zcorn().value(v)) << "ZCORN value " << v;
    ASSERT_NE(block.grid.dynamic_property("SWAT", 40), nullptr);
    EXPECT_EQ(*block.grid.dynamic_property("SWAT", 40),
              grid::box_values(*whole.grid.dynamic_property("SWAT", 40), whole.grid.dims(), box));
}

TEST(CaseModel, ReadingEveryStepHoldsOneStep) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer's allocator does not report to mallinfo2";
#else
    // glibc's count of bytes in use (mallinfo2().uordblks) after each step: EclIO keeps every array
    // it reads until its file closes, so a reader that kept one ERst open would grow by the step's
    // restart arrays (4 bytes per active cell each) at every step; ours reads each step from a fresh
    // ERst and the grid releases the step before. Allowed growth: one step's arrays (read_bytes),
    // for allocator slack.
    LoadedModel model = load_model({spe9}, memory_limit, std::string("SWAT"));
    hold_property(model, "SWAT", 0, memory_limit);
    const std::size_t first = mallinfo2().uordblks;
    std::size_t most = first;
    for (int step = 1; step < int(model.report_steps->step_count()); ++step) {
        hold_property(model, "SWAT", step, memory_limit);
        hold_property(model, "SOIL", step, memory_limit);
        most = std::max(most, std::size_t(mallinfo2().uordblks));
    }
    EXPECT_LE(most - first, model.report_steps->read_bytes()) << "bytes in use grew over 89 step reads";
    RecordProperty("bytes_in_use_growth", std::to_string(most - first));
    RecordProperty("read_bytes", std::to_string(model.report_steps->read_bytes()));
#endif
}

}  // namespace
}  // namespace cutaway::app
