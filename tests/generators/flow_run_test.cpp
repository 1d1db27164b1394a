// End to end (label "opm"): `cutaway generate --deck` writes a deck, OPM Flow runs it as it is,
// and its restart file (read through opm-common's EclIO) holds every report step and a water
// front that has crossed much of the field by the last one.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <opm/io/eclipse/ERst.hpp>

#include "cutaway_process.h"
#include "generators/flow_fluid_model.h"
#include "generators/flow_schedule.h"

namespace {

namespace fs = std::filesystem;
using cutaway::testing::ProcessResult;
using cutaway::testing::run_process;

/// Share of cells whose SWAT at `step` exceeds the initial SWAT by more than 0.1 (a tenth of
/// the saturation range, far above the solver's tolerance): cells the water front has reached.
double swept_share(Opm::EclIO::ERst& restart, const std::vector<float>& initial, int step) {
    const std::vector<float> swat = restart.getRestartData<float>("SWAT", step);
    std::size_t swept = 0;
    for (std::size_t c = 0; c < swat.size(); ++c) swept += swat[c] > initial[c] + 0.1f;
    return double(swept) / double(swat.size());
}

TEST(FlowDeckRun, ZaphirusWaterfloodCrossesTheField) {
    const fs::path scratch = fs::temp_directory_path() / ("cutaway_flow_run_" + std::to_string(::getpid()));
    fs::remove_all(scratch);
    fs::create_directories(scratch);
    const fs::path deck = scratch / "deck", results = scratch / "results";

    const ProcessResult generated =
        run_process(CUTAWAY_EXE, {"generate", "--preset", "zaphirus", "--seed", "1", "--quiet", "--deck", deck.string()},
                    scratch);
    ASSERT_EQ(generated.exit_code, 0) << generated.err;
    ASSERT_TRUE(fs::exists(deck / "ZAPHIRUS.DATA"));
    ASSERT_TRUE(fs::exists(deck / "ZAPHIRUS.GRDECL"));

    const ProcessResult flow = run_process(CUTAWAY_FLOW, {(deck / "ZAPHIRUS.DATA").string(),
                                                          "--output-dir=" + results.string(),
                                                          "--threads-per-process=2", "--enable-terminal-output=false"},
                                           scratch);
    ASSERT_EQ(flow.exit_code, 0) << flow.out << flow.err;
    for (const char* extension : {".EGRID", ".INIT", ".UNRST"})
        ASSERT_TRUE(fs::exists(results / (std::string("ZAPHIRUS") + extension))) << extension;

    Opm::EclIO::ERst restart((results / "ZAPHIRUS.UNRST").string());
    std::vector<int> expected_steps(cutaway::generators::kDeckReportSteps + 1);  // the initial state and every step
    for (std::size_t s = 0; s < expected_steps.size(); ++s) expected_steps[s] = int(s);
    ASSERT_EQ(restart.listOfReportStepNumbers(), expected_steps);

    // The whole model starts at connate water (the oil-water contact lies below it).
    const std::vector<float> initial = restart.getRestartData<float>("SWAT", 0);
    for (float swat : initial) ASSERT_NEAR(swat, cutaway::generators::flow_fluids::connate_water, 1e-3);
    // The front moves on between the middle and the last step and has reached most of the field
    // by the end. The schedule injects kInjectedPoreVolumes (0.8) of water into oil of lower
    // mobility, so a working flood sweeps far more than 60% of the cells; a flood whose
    // injectors stall at their pressure limit, or a schedule too short for the front to cross,
    // stays below it.
    const double middle = swept_share(restart, initial, cutaway::generators::kDeckReportSteps / 2);
    const double last = swept_share(restart, initial, cutaway::generators::kDeckReportSteps);
    EXPECT_GT(middle, 0.2);
    EXPECT_GT(last, middle + 0.05);
    EXPECT_GT(last, 0.6);
    fs::remove_all(scratch);
}

}  // namespace
