// Issue 47: nothing a user owns is overwritten or left half-written. Outputs are compared with
// each other and with every input as files (however spelled); the outputs of one run are
// committed together or not at all; an interrupted run leaves no temporary file; and the smaller
// refusals (empty names, wrapped seeds, symbolic link loops, FIFOs, long paths, degenerate grids).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include "bad_input_fixture.h"

namespace {

using namespace cutaway::testing;  // the fixture, its checks and the shared inputs
namespace fs = std::filesystem;

fs::path seismic_cube() { return fs::path(CUTAWAY_SHARED_DATA) / "segy" / "f3.sgy"; }

// ---- outputs compared as files -----------------------------------------------------------------

TEST_F(BadInput, OutputsSpelledDifferentlyAreOneFile) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const std::string model_bytes = contents(grid);
    const std::string dotted = (scratch_ / "out" / "." / "x.png").string();
    const std::string detour = (scratch_ / "out" / ".." / "out" / "x.png").string();
    const std::string relative = "./" + fs::relative(out("st.json")).string();
    expect_refused(cutaway({"render", grid, "--out", out("x.png"), "--cell-ids", dotted}),
                   {"--cell-ids", "expected a file other than --out's", "same file"});
    expect_refused(cutaway({"render", grid, "--out", out("x.png"), "--stats", detour}), {"--stats", "--out's", "same file"});
    expect_refused(cutaway({"render", grid, "--out", out("y.png"), "--stats", relative, "--cell-ids", out("st.json")}),
                   {"--stats", "--cell-ids's", "same file"});
    expect_refused(cutaway({"volume", seismic_cube(), "--caster", "cpu", "--out", dotted, "--stats", out("x.png")}),
                   {"--stats", "--out's", "same file"});
    // A symbolic link and a hard link to the model are the model.
    fs::create_symlink(grid, scratch_ / "link.grdecl");
    fs::create_hard_link(grid, scratch_ / "hard.grdecl");
    expect_refused(cutaway({"inspect", grid, "--cells-csv", (scratch_ / "link.grdecl").string()}),
                   {"--cells-csv", "the model's", "same file"});
    expect_refused(cutaway({"render", grid, "--out", (scratch_ / "hard.grdecl").string()}), {"--out", "the model's", "same file"});
    EXPECT_EQ(contents(grid), model_bytes) << "the model was overwritten";
    expect_no_output();
}

TEST_F(BadInput, OutputNamingAnIncludeIsRefusedBeforeTheIncludeIsRead) {
    std::string grid_text = kTinyGrid;
    const std::size_t poro = grid_text.find("PORO");
    const std::string poro_text = grid_text.substr(poro, grid_text.find("FACIES") - poro);
    grid_text.replace(poro, poro_text.size(), "INCLUDE\n 'poro.inc' /\n");
    const fs::path grid = file("main.grdecl", grid_text);
    const fs::path include = file("poro.inc", poro_text);
    expect_refused(cutaway({"inspect", grid, "--cells-csv", include}),
                   {"--cells-csv", "the INCLUDE at", "main.grdecl:", "same file"});
    expect_refused(cutaway({"render", grid, "--out", out("x.png"), "--stats", (scratch_ / "." / "poro.inc").string()}),
                   {"--stats", "the INCLUDE at", "same file"});
    EXPECT_EQ(contents(include), poro_text) << "the INCLUDE was overwritten";
    expect_no_output();
}

TEST_F(BadInput, ViewerOutputsNeverOverwriteTheScriptOrTheModel) {
    // Refused before a window opens (no display is needed to see the refusal).
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const fs::path shooting = file("shoot.txt", "screenshot " + grid.string() + "\nquit\n");
    expect_refused(cutaway({"view", grid, "--script", shooting}), {"shoot.txt:1: screenshot", "the model's", "same file"});
    const fs::path quitting = file("quit.txt", "quit\n");
    expect_refused(cutaway({"view", grid, "--script", quitting, "--screenshot", quitting}),
                   {"--screenshot", "--script's", "same file"});
    EXPECT_EQ(contents(grid), kTinyGrid);
    EXPECT_EQ(contents(quitting), "quit\n");
    expect_no_output();
}

// ---- outputs committed together, none left by a failure or an interrupt ----------------------

TEST_F(BadInput, FailedStatsLeavesNoImage) {
    // The image is written before the stats: it must not stay when the stats cannot be written.
    for (const std::string stats : {"/dev/full", "/proc/cutaway-stats.json"}) {
        SCOPED_TRACE(stats);
        const ProcessResult r = cutaway({"volume", seismic_cube(), "--caster", "cpu", "--size", "32", "32", "--out",
                                         out("v.png"), "--stats", stats});
        expect_refused(r, {stats});
        EXPECT_EQ(r.out, "") << "a report printed for a run that failed";
        expect_no_output();
    }
}

TEST_F(BadInput, InterruptedGenerateLeavesNoPartialFile) {
    // 100 x 100 x 40 cells write about 20 MB of text: the signal comes while the file is written.
    for (const auto& [signal, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
        SCOPED_TRACE(signal);
        ProcessLimits limits;
        limits.interrupt_signal = signal;
        limits.interrupt_watch = scratch_ / "out";
        const ProcessResult r =
            cutaway({"generate", "--dims", "100", "100", "40", "--seed", "1", "--quiet", "--out", out("g.grdecl")}, limits);
        EXPECT_TRUE(r.interrupted) << "no staged file appeared";
        EXPECT_EQ(r.exit_code, code) << r.err;
        expect_no_output();
    }
}

TEST_F(BadInput, InterruptedCellsCsvLeavesNoPartialFileAndTheModelUnchanged) {
    const fs::path grid = scratch_ / "model.grdecl";
    const ProcessResult generated =
        cutaway({"generate", "--dims", "100", "100", "20", "--seed", "1", "--quiet", "--out", grid.string()});
    ASSERT_EQ(generated.exit_code, 0) << generated.err;
    const std::string model_bytes = contents(grid);
    ProcessLimits limits;
    limits.interrupt_signal = SIGTERM;
    limits.interrupt_watch = scratch_ / "out";
    const ProcessResult r = cutaway({"inspect", grid, "--cells-csv", out("cells.csv")}, limits);
    EXPECT_TRUE(r.interrupted) << "no staged file appeared";
    EXPECT_EQ(r.exit_code, 143) << r.err;
    EXPECT_EQ(contents(grid), model_bytes);
    expect_no_output();
}

// ---- smaller refusals ----------------------------------------------------------------------------

TEST_F(BadInput, EmptyNamesAndWrappingNumbersAreRefused) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(cutaway({"render", grid, "--property", "", "--out", out("x.png")}), {"--property", "found an empty one"});
    expect_refused(cutaway({"render", grid, "--select-by", "", "--out", out("x.png")}), {"--select-by", "found an empty one"});
    // An unsigned seed would take -1 as 2^64 - 1.
    expect_refused(cutaway({"generate", "--dims", "2", "2", "2", "--seed", "-1", "--out", out("g.grdecl")}),
                   {"--seed", "[0, ", "'-1'"});
    expect_refused(cutaway({"generate-seismic", "--dims", "8", "8", "8", "--seed", "-1", "--out", out("s.sgy")}),
                   {"--seed", "'-1'"});
    expect_no_output();
}

TEST_F(BadInput, StepOfTheSelectingPropertyIsCheckedAgainstIt) {
    // --step belongs to the dynamic --select-by property, not the static colouring one (PORO).
    const fs::path grid = scratch_ / "flood.grdecl";
    const ProcessResult generated =
        cutaway({"generate", "--dims", "4", "4", "2", "--seed", "1", "--time-steps", "2", "--quiet", "--out", grid.string()});
    ASSERT_EQ(generated.exit_code, 0) << generated.err;
    const ProcessResult r = cutaway({"render", grid, "--select-by", "SWAT", "--step", "3", "--out", out("x.png")});
    expect_refused(r, {"--select-by", "--time-step 3", "property SWAT has 2 time steps"});
    EXPECT_EQ(r.err.find("PORO"), std::string::npos) << r.err;
    expect_no_output();
}

TEST_F(BadInput, OptionErrorsAreOneLineNamingTheSubcommand) {
    const ProcessResult r = cutaway({"render", "preset:zaphirus", "--size", "2", "2", "--out", out("x.png")});
    expect_refused(r, {"--size", "cutaway render --help"});
    EXPECT_EQ(r.err.find("SUBCOMMAND"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
}

TEST_F(BadInput, NonFinitePropertiesAreRefusedByInspectAsByRender) {
    for (const std::string value : {"nan", "inf", "-inf"}) {
        SCOPED_TRACE(value);
        std::string text = kTinyGrid;
        text.replace(text.find("0.2 0.3"), 3, value);
        const ProcessResult r = cutaway({"inspect", file("bad.grdecl", text), "--json"});
        expect_refused(r, {"property PORO", "active cell (i,j,k) = (1,0,0)", "expected a finite number"});
        EXPECT_EQ(r.out, "") << "a report for a model render refuses";
    }
}

TEST_F(BadInput, SymbolicLinkLoopIsReportedAsALoop) {
    fs::create_symlink(scratch_ / "b.grdecl", scratch_ / "a.grdecl");
    fs::create_symlink(scratch_ / "a.grdecl", scratch_ / "b.grdecl");
    expect_refused(cutaway({"inspect", (scratch_ / "a.grdecl").string()}), {"a.grdecl", "a loop of symbolic links"});
    expect_refused(cutaway({"volume", (scratch_ / "a.grdecl").string(), "--out", out("v.png")}),
                   {"a.grdecl", "a loop of symbolic links"});
    fs::create_symlink(scratch_ / "missing.grdecl", scratch_ / "dangling.grdecl");
    expect_refused(cutaway({"inspect", (scratch_ / "dangling.grdecl").string()}), {"a symbolic link to a missing file"});
    expect_no_output();
}

TEST_F(BadInput, LongPathsAreShortenedInMessages) {
    std::string deep = scratch_.string();
    while (deep.size() < 5000) deep += "/" + std::string(200, 'd');
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"inspect", deep + "/model.grdecl"},
          std::vector<std::string>{"render", file("tiny.grdecl", kTinyGrid), "--out", deep + "/x.png"},
          std::vector<std::string>{"volume", deep + "/cube.sgy", "--out", out("v.png")}}) {
        SCOPED_TRACE(args[0]);
        const ProcessResult r = cutaway(args);
        EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 300);
        EXPECT_LT(r.err.size(), std::size_t(600)) << "the path was echoed whole";
    }
    expect_no_output();
}

TEST_F(BadInput, FifoScriptIsRefusedWithoutWaiting) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const fs::path fifo = scratch_ / "script.fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const ProcessResult r = cutaway({"view", grid, "--script", fifo});
    expect_refused(r, {"script.fifo", "a FIFO"});
    EXPECT_LT(r.seconds, 10);
}

TEST_F(BadInput, EveryCommandHasOneDefaultMemoryLimit) {
    for (const std::string command : {"inspect", "generate", "render", "volume", "generate-seismic", "view"}) {
        SCOPED_TRACE(command);
        const ProcessResult r = cutaway({command, "--help"});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const std::size_t option = r.out.find("--memory-limit-gb");
        ASSERT_NE(option, std::string::npos) << r.out;
        const std::string line = r.out.substr(option, r.out.find('\n', option) - option);
        EXPECT_NE(line.find("GiB=16"), std::string::npos) << line;
    }
}

// ---- no silent blanks --------------------------------------------------------------------------

TEST_F(BadInput, SeismicCubesThatWouldDrawBlankAreRefused) {
    const fs::path flat = file("flat.sgy", segy_bytes(8, 5, 8, [](int, int) { return 0.0f; }));
    expect_refused(cutaway({"volume", flat, "--caster", "cpu", "--out", out("v.png")}),
                   {"flat.sgy", "expected amplitudes that vary", "every sample equal to 0"});
    // 20 traces on the diagonal of a 20 x 20 survey: 380 of 400 (95%) missing.
    const fs::path sparse = file("sparse.sgy", segy_bytes(8, 5, 8, [](int, int k) { return float(k); }, 20,
                                                          [](int t) { return TraceLines{1 + t, 1 + t}; }));
    const ProcessResult r = cutaway({"volume", sparse, "--caster", "cpu", "--out", out("v.png")});
    expect_refused(r, {"sparse.sgy", "at least 10% of its traces present", "380 of 400 missing"});
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
    // f3.sgy is 23 x 18 x 75 voxels: a million voxels away it covers a few hundredths of a pixel.
    expect_refused(cutaway({"volume", seismic_cube(), "--caster", "cpu", "--camera", "0", "30", "1e6", "--out", out("v.png")}),
                   {"--camera", "covers under a pixel"});
    expect_no_output();
}

// ---- geometry sanity before allocation ------------------------------------------------------

TEST_F(BadInput, PillarsAtOnePointAreRefusedFromCoordAlone) {
    // 88 bytes declaring 1000 x 1000 x 100 cells, every pillar at one point, ZCORN and PORO by
    // repeat counts: once this took 6 GB and 11 s; now COORD alone refuses it.
    const fs::path grid = file("point.grdecl",
                               "SPECGRID\n1000 1000 100 1 F /\nCOORD\n6012006*0 /\nZCORN\n800000000*0 /\n"
                               "PORO\n100000000*0.2 /\n");
    for (const std::vector<std::string>& args : {std::vector<std::string>{"inspect", grid.string()},
                                                 std::vector<std::string>{"render", grid.string(), "--out", out("x.png")}}) {
        SCOPED_TRACE(args[0]);
        const ProcessResult r = cutaway(args);
        expect_refused(r, {"point.grdecl:3", "COORD", "pillars spanning a horizontal area", "all 1002001 pillars"});
        EXPECT_LT(r.seconds, 5);
        if (kMeasureMemory) {
            EXPECT_LT(r.peak_rss_mb, 48 + kBaselineRssMb);  // COORD is 48 MB as doubles
        }
    }
    expect_no_output();
}

TEST_F(BadInput, GridOfCoincidingPillarsIsRefusedFromCoordAlone) {
    // The pillars span an area (half at x = y = 0, half at 1), but almost every one equals its
    // neighbour: 1000 x 1000 x 100 cells without width, declared in 98 bytes.
    const fs::path grid = file("pairs.grdecl",
                               "SPECGRID\n1000 1000 100 1 F /\nCOORD\n3006003*0 3006003*1 /\nZCORN\n800000000*0 /\n"
                               "PORO\n100000000*0.2 /\n");
    const ProcessResult r = cutaway({"inspect", grid.string()});
    expect_refused(r, {"pairs.grdecl:3", "COORD", "pillars at distinct places", "equal to their neighbour along i"});
    EXPECT_LT(r.seconds, 5);
    if (kMeasureMemory) {
        EXPECT_LT(r.peak_rss_mb, 48 + kBaselineRssMb);  // COORD is 48 MB as doubles
    }
}

}  // namespace
