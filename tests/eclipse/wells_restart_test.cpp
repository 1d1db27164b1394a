// Wells of SPE9 three ways: our deck reader, opm-common's Schedule on the same deck (an independent
// reference), and the restart file OPM Flow writes (ZWEL, IWEL, ICON at each report step).
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include <opm/input/eclipse/Deck/Deck.hpp>
#include <opm/input/eclipse/EclipseState/EclipseState.hpp>
#include <opm/input/eclipse/Parser/Parser.hpp>
#include <opm/input/eclipse/Python/Python.hpp>
#include <opm/input/eclipse/Schedule/Schedule.hpp>
#include <opm/input/eclipse/Schedule/Well/Well.hpp>

#include "app_core/model_source.h"
#include "io/bad_input_error.h"
#include "wells/deck_wells.h"
#include "wells/restart_wells.h"

namespace cutaway::wells {
namespace {

namespace fs = std::filesystem;
const fs::path spe9_case = fs::path(CUTAWAY_FLOW_CASES) / "spe9" / "SPE9";
const fs::path spe9_deck = fs::path(CUTAWAY_SHARED_DATA) / "opm/spe9/SPE9.DATA";

TEST(Spe9Wells, DeckReaderAgreesWithOpmsSchedule) {
    const std::vector<Well> ours = read_deck_wells(spe9_deck);
    const Opm::Deck deck = Opm::Parser().parseFile(spe9_deck.string());
    const Opm::EclipseState state(deck);
    const Opm::Schedule schedule(deck, state, std::make_shared<Opm::Python>());
    const std::vector<Opm::Well> reference = schedule.getWells(0);
    ASSERT_EQ(ours.size(), reference.size());
    ASSERT_EQ(ours.size(), 26u);
    for (const Opm::Well& theirs : reference) {
        const auto mine = std::find_if(ours.begin(), ours.end(), [&](const Well& w) { return w.name == theirs.name(); });
        ASSERT_NE(mine, ours.end()) << theirs.name();
        EXPECT_EQ(mine->head_i, theirs.getHeadI()) << theirs.name();
        EXPECT_EQ(mine->head_j, theirs.getHeadJ()) << theirs.name();
        EXPECT_EQ(mine->kind == WellKind::injector, theirs.isInjector()) << theirs.name();
        const Opm::WellConnections& connections = theirs.getConnections();
        ASSERT_EQ(mine->connections.size(), connections.size()) << theirs.name();
        for (std::size_t c = 0; c < connections.size(); ++c) {
            EXPECT_EQ(mine->connections[c].i, connections[c].getI());
            EXPECT_EQ(mine->connections[c].j, connections[c].getJ());
            EXPECT_EQ(mine->connections[c].k, connections[c].getK());
        }
    }
}

TEST(Spe9Wells, RestartStepsHoldTheDecksWellsTypesAndConnections) {
    const app::LoadedModel model = app::load_model({spe9_case.string() + ".EGRID"}, std::size_t(4) << 30);
    ASSERT_TRUE(model.report_steps);
    const std::vector<Well> deck = read_deck_wells(spe9_deck);
    for (const std::size_t step : {std::size_t(0), model.report_steps->step_count() - 1}) {
        const std::vector<Well> restart = restart_wells(*model.report_steps, step);
        ASSERT_EQ(restart.size(), deck.size()) << "step " << step;
        for (std::size_t w = 0; w < deck.size(); ++w) {
            EXPECT_EQ(restart[w].name, deck[w].name);
            EXPECT_EQ(restart[w].kind, deck[w].kind) << deck[w].name;
            EXPECT_EQ(restart[w].injected_phase, deck[w].injected_phase) << deck[w].name;
            EXPECT_EQ(restart[w].head_i, deck[w].head_i) << deck[w].name;
            EXPECT_EQ(restart[w].head_j, deck[w].head_j) << deck[w].name;
            ASSERT_EQ(restart[w].connections.size(), deck[w].connections.size()) << deck[w].name;
            for (std::size_t c = 0; c < deck[w].connections.size(); ++c) {
                EXPECT_EQ(restart[w].connections[c].k, deck[w].connections[c].k) << deck[w].name;
                EXPECT_EQ(restart[w].connections[c].i, deck[w].connections[c].i) << deck[w].name;
                EXPECT_TRUE(restart[w].connections[c].open) << deck[w].name;
            }
        }
    }
    EXPECT_THROW(restart_wells(*model.report_steps, model.report_steps->step_count()), io::BadInputError);
}

}  // namespace
}  // namespace cutaway::wells
