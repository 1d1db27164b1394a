// The bad-input contract of `cutaway` (issue 18), run as a user runs the program: every case is a
// small file written here or a command line, and each asserts the exit code (2: bad input), that
// the message names the file, keyword or option and says what was expected, that no output (and
// no partial output) is left behind, and for the memory cases the child's peak resident memory.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bad_input_fixture.h"
#include "cutaway/cell_id_image.h"
#include "gl/image.h"

namespace {

using namespace cutaway::testing;  // the fixture, its checks and the shared inputs
namespace fs = std::filesystem;

// ---- outputs -------------------------------------------------------------------------------

TEST_F(BadInput, SamePathForTwoOutputsIsRefusedBeforeRendering) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const ProcessResult r = cutaway({"render", grid, "--out", out("x.png"), "--stats", out("x.png")});
    expect_refused(r, {"--stats", "--out", "same file"});
    expect_no_output();
    // An output naming an input would overwrite it.
    expect_refused(cutaway({"inspect", grid, "--cells-csv", grid}), {"--cells-csv", "the model", "same file"});
    EXPECT_EQ(fs::file_size(grid), std::string(kTinyGrid).size()) << "the model was overwritten";
    // The viewer refuses before it opens a window (no display is needed to see the refusal).
    expect_refused(cutaway({"view", grid, "--screenshot", out("v.png"), "--stats", out("v.png")}),
                   {"--stats", "--screenshot", "same file"});
    expect_no_output();
}

TEST_F(BadInput, FailedCellsCsvWritePrintsNoReport) {
    // A report on stdout followed by exit 2 would read as half a success.
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const ProcessResult r = cutaway({"inspect", grid, "--cells-csv", "/dev/full"});
    expect_refused(r, {"/dev/full", "No space left on device"});
    EXPECT_EQ(r.out, "") << "the report was printed before the failed write";
}

TEST_F(BadInput, MissingOutputDirectoryIsRefusedBeforeReadingTheModel) {
    const ProcessResult r = cutaway({"render", "preset:sapphire", "--out", out("no/such/dir/x.png")});
    expect_refused(r, {"--out", "no directory", "no/such/dir"});
    EXPECT_LT(r.seconds, 5) << "refused only after generating the model";
}

TEST_F(BadInput, EmptyOutputPathIsRefused) {
    expect_refused(cutaway({"render", "preset:sapphire", "--out", ""}), {"--out", "empty path"});
    expect_refused(cutaway({"volume", "cube.sgy", "--out", out("v.png"), "--stats", ""}), {"--stats", "empty path"});
}

TEST_F(BadInput, OutputThatIsADirectoryIsRefused) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(cutaway({"inspect", grid, "--cells-csv", (scratch_ / "out").string()}), {"--cells-csv", "directory"});
}

TEST_F(BadInput, FullDiskIsExit2NamingThePathAndTheReason) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(cutaway({"inspect", grid, "--cells-csv", "/dev/full"}), {"/dev/full", "No space left on device"});
    const fs::path cube = fs::path(CUTAWAY_SHARED_DATA) / "segy" / "f3.sgy";
    expect_refused(cutaway({"volume", cube, "--caster", "cpu", "--size", "32", "32", "--out", "/dev/full"}),
                   {"/dev/full", "No space left on device"});
    expect_refused(cutaway({"volume", cube, "--caster", "cpu", "--size", "32", "32", "--out", out("v.png"), "--stats",
                            "/dev/full"}),
                   {"/dev/full", "No space left on device"});
    expect_refused(cutaway({"generate", "--dims", "4", "4", "2", "--seed", "1", "--quiet", "--out", "/dev/full"}),
                   {"/dev/full", "No space left on device"});
}

TEST_F(BadInput, DeckWriteFailingHalfWayLeavesNoDeck) {
    // The deck's grid file of 10 x 12 x 3 cells (COORD and ZCORN) is far above the 16 kB the child
    // may write: the deck folder it made goes with the partial file.
    ProcessLimits limits;
    limits.max_file_bytes = 16384;
    const ProcessResult r =
        cutaway({"generate", "--dims", "10", "12", "3", "--seed", "1", "--quiet", "--deck", out("deck")}, limits);
    expect_refused(r, {"CUSTOM.GRDECL", "expected the output written whole", "File too large"});
    expect_no_output();
}

TEST_F(BadInput, WriteFailingHalfWayLeavesNoPartialFile) {
    // 20 x 20 x 10 cells make a CSV of about 200 kB; the child may write only 4 kB.
    const ProcessResult generated =
        cutaway({"generate", "--dims", "20", "20", "10", "--seed", "1", "--quiet", "--out", (scratch_ / "grid.grdecl").string()});
    ASSERT_EQ(generated.exit_code, 0) << generated.err;
    ProcessLimits limits;
    limits.max_file_bytes = 4096;
    const ProcessResult r = cutaway({"inspect", (scratch_ / "grid.grdecl").string(), "--cells-csv", out("cells.csv")}, limits);
    expect_refused(r, {"cells.csv", "File too large"});
    expect_no_output();
}

// ---- numeric options -------------------------------------------------------------------------

struct OptionCase {
    std::vector<std::string> args;  ///< after the subcommand and its input
    std::vector<std::string> message;
};

TEST_F(BadInput, RenderOptionsOutsideTheirRangeAreRefusedWithTheRange) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const std::vector<OptionCase> cases = {
        {{"--camera", "nan", "nan", "nan"}, {"--camera", "AZ", "[-360, 360]", "nan"}},
        {{"--camera", "0", "95", "0"}, {"--camera", "EL", "[-89, 89]"}},
        {{"--camera", "0", "0", "-1"}, {"--camera", "DIST"}},
        {{"--freeze-camera", "nan", "0", "0"}, {"--freeze-camera", "AZ"}},
        {{"--z-scale", "nan"}, {"--z-scale", "[0, 1000]", "nan"}},
        {{"--z-scale", "1e30"}, {"--z-scale", "[0, 1000]", "1e30"}},
        {{"--z-scale", "-5"}, {"--z-scale", "[0, 1000]"}},
        {{"--back-margin", "nan"}, {"--back-margin", "[0, 1]"}},
        {{"--back-margin", "-10"}, {"--back-margin", "[0, 1]"}},
        {{"--range", "nan", "nan"}, {"--range", "finite"}},
        {{"--range", "0.3", "0.1"}, {"--range", "LO <= HI"}},
        {{"--colour-range", "nan", "1"}, {"--colour-range", "finite"}},
        {{"--colour-range", "0.3", "0.1"}, {"--colour-range", "LO < HI"}},
        {{"--colour-range", "0.2", "0.2"}, {"--colour-range", "LO < HI"}},
        {{"--primary-fraction", "0"}, {"--primary-fraction", "(0, 1]"}},
        {{"--primary-fraction", "-0.5"}, {"--primary-fraction", "(0, 1]"}},
        {{"--primary-fraction", "nan"}, {"--primary-fraction", "(0, 1]"}},
        {{"--time-step", "-1"}, {"--time-step", "[0, 1e+06]"}},
        {{"--step", "-1"}, {"--time-step", "[0, 1e+06]"}},  // --step: the older name of --time-step
        {{"--memory-limit-gb", "-1"}, {"--memory-limit-gb", "GiB"}},
        {{"--memory-limit-gb", "nan"}, {"--memory-limit-gb", "GiB"}},
        {{"--silhouette-width", "100000"}, {"--silhouette-width", "[1, 64] pixels"}},
        {{"--silhouette-width", "-3"}, {"--silhouette-width", "[1, 64] pixels"}},
        {{"--aperture", "nan", "30"}, {"--aperture", "[0, 180] degrees"}},
        {{"--size", "100000", "100"}, {"--size", "[16, 32768] pixels"}},
        {{"--size", "0", "100"}, {"--size", "[16, 32768] pixels"}},
        {{"--repeat", "100000000"}, {"--repeat", "[1, 1000]"}},
        {{"--egl-platform", "bogus"}, {"--egl-platform", "auto|surfaceless|device", "bogus"}},
        {{"--ijk-box", "0", "0", "0", "5", "1", "0"}, {"--ijk-box", "2 x 2 x 1", "0 0 0 5 1 0"}},
    };
    for (const OptionCase& c : cases) {
        std::vector<std::string> args{"render", grid.string(), "--out", out("x.png")};
        args.insert(args.end(), c.args.begin(), c.args.end());
        SCOPED_TRACE(::testing::PrintToString(c.args));
        expect_refused(cutaway(args), c.message);
    }
    expect_no_output();
}

TEST_F(BadInput, VolumeOptionsOutsideTheirRangeAreRefusedWithTheRange) {
    const fs::path cube = fs::path(CUTAWAY_SHARED_DATA) / "segy" / "f3.sgy";
    const std::vector<OptionCase> cases = {
        {{"--opacity", "nan"}, {"--opacity", "[0, 1]"}},
        {{"--camera", "nan", "0", "0"}, {"--camera", "AZ"}},
        {{"--time-scale", "1e30"}, {"--time-scale", "[0, 1000]"}},
        {{"--step", "-1"}, {"--step", "(0.01, 16] voxels"}},
        {{"--repeat", "100000000"}, {"--repeat", "[1, 1000]"}},
        {{"--threads", "100000"}, {"--threads", "[0, 256]"}},
        {{"--layer", "1", "0", "1", "255"}, {"--layer", "R", "(0, 255]"}},
        {{"--caster", "gpx"}, {"--caster", "gpu|cpu"}},
        {{"--camera", "0", "0", "1"}, {"--camera", "inside the cube"}},
    };
    for (const OptionCase& c : cases) {
        std::vector<std::string> args{"volume", cube.string(), "--caster", "cpu", "--out", out("v.png")};
        args.insert(args.end(), c.args.begin(), c.args.end());
        SCOPED_TRACE(::testing::PrintToString(c.args));
        expect_refused(cutaway(args), c.message);
    }
    expect_no_output();
}

TEST_F(BadInput, ViewAndGeneratorOptionsAreChecked) {
    expect_refused(cutaway({"view", "preset:zaphirus", "--size", "100000", "100000"}), {"--size", "[16, 32768]"});
    // CLI::Range let NaN through (every comparison with NaN is false).
    expect_refused(cutaway({"view", "preset:zaphirus", "--render-scale", "nan"}), {"--render-scale", "[0.25, 1]"});
    expect_refused(cutaway({"generate-seismic", "--dims", "8", "8", "16", "--noise", "inf", "--out", out("s.sgy")}),
                   {"--noise", "a finite number", "'inf'"});
    expect_refused(cutaway({"generate", "--dims", "4", "4", "2", "--top-depth", "nan", "--out", out("g.grdecl")}),
                   {"--top-depth", "a finite number"});
    const ProcessResult r = cutaway({"generate", "--dims", "2147483647", "1", "1", "--out", out("g.grdecl")});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.find("18446744073"), std::string::npos) << "overflowed estimate: " << r.err;
    EXPECT_NE(r.err.find("memory limit"), std::string::npos) << r.err;
}

// ---- one memory budget ----------------------------------------------------------------------

TEST_F(BadInput, RenderTargetsAreRefusedBeforeAllocating) {
    // 4096 x 4096 pixels at 160 bytes each need 2.5 GiB, beyond 0.5 GiB.
    const ProcessResult r = cutaway({"render", "preset:zaphirus", "--size", "4096", "4096", "--memory-limit-gb", "0.5",
                                     "--out", out("x.png")});
    expect_refused(r, {"--size", "memory limit of 0.5 GiB", "2.5 GiB needed"});
    if (kMeasureMemory) {
        EXPECT_LT(r.peak_rss_mb, kBaselineRssMb);
    }
    const fs::path cube = fs::path(CUTAWAY_SHARED_DATA) / "segy" / "f3.sgy";
    const ProcessResult v = cutaway({"volume", cube, "--size", "8192", "8192", "--memory-limit-gb", "0.1", "--out", out("v.png")});
    expect_refused(v, {"--size", "memory limit of 0.1 GiB"});
    if (kMeasureMemory) {
        EXPECT_LT(v.peak_rss_mb, kBaselineRssMb);
    }
    expect_no_output();
}

TEST_F(BadInput, SeismicCubeOverTheLimitIsRefusedBeforeItsSamplesAreRead) {
    // f3.sgy: 23 x 18 x 75 = 31050 samples at 6 bytes (float, level, texture) = 182 KiB; the limit
    // of 0.0001 GiB (105 KiB) less the 16 x 16 frame (12 KiB) leaves 93 KiB.
    const fs::path cube = fs::path(CUTAWAY_SHARED_DATA) / "segy" / "f3.sgy";
    const ProcessResult r = cutaway({"volume", cube, "--caster", "cpu", "--size", "16", "16", "--memory-limit-gb", "0.0001",
                                     "--out", out("v.png")});
    expect_refused(r, {"f3.sgy", "the traces", "expected at most the memory limit of"});
    if (kMeasureMemory) {
        EXPECT_LT(r.peak_rss_mb, kBaselineRssMb);
    }
    expect_no_output();
}

TEST_F(BadInput, LargeFileIsRefusedBeforeItIsRead) {
    // A sparse 2 GB file costs no disk; reading it whole took 2.1 GB and 12 s before.
    const fs::path big = scratch_ / "big.grdecl";
    { std::ofstream(big) << "-- sparse\n"; }
    fs::resize_file(big, std::uintmax_t(2) << 30);
    const ProcessResult r = cutaway({"inspect", big, "--memory-limit-gb", "0.5"});
    expect_refused(r, {"big.grdecl", "memory limit"});
    EXPECT_LT(r.seconds, 1);
    if (kMeasureMemory) {
        EXPECT_LT(r.peak_rss_mb, kBaselineRssMb);
    }

    // Nested INCLUDEs count together: 0.3 GiB + 0.3 GiB held at once exceed 0.5 GiB.
    const fs::path inner = scratch_ / "inner.grdecl";
    { std::ofstream(inner) << "-- sparse\n"; }
    fs::resize_file(inner, std::uintmax_t(300) << 20);
    const fs::path middle = file("middle.grdecl", "INCLUDE\n 'inner.grdecl' /\n");
    fs::resize_file(middle, std::uintmax_t(300) << 20);  // sparse: zeros after the INCLUDE, never parsed
    const fs::path top = file("top.grdecl", "INCLUDE\n 'middle.grdecl' /\n");
    const ProcessResult n = cutaway({"inspect", top, "--memory-limit-gb", "0.5"});
    expect_refused(n, {"INCLUDE", "inner.grdecl", "already held"});
    if (kMeasureMemory) {
        EXPECT_LT(n.peak_rss_mb, 512 + kBaselineRssMb);
    }
}

TEST_F(BadInput, ZcornFullLayoutIsReservedBeforeItIsAllocated) {
    // 200 x 200 x 100 cells: COORD 1.9 MB, compact ZCORN 129 MB, full ZCORN 256 MB; the limit
    // (0.3 GiB = 322 MB) admits the compact store but not both at once. Before the fix the full
    // array was allocated first (peak 385 MB).
    const ProcessResult r = refused_half_zero_zcorn("zcorn.grdecl", 200, 200, 100, "0.3");
    if (kMeasureMemory) {
        EXPECT_LT(r.peak_rss_mb, 0.3 * 1024 + kBaselineRssMb);
    }
}

TEST_F(BadInput, ZcornOfZerosIsRefusedWithoutTouchingItsStore) {
    // Issue 18's reproducer: 1000 x 1000 x 100 cells, 400M zero depths then 400M ones. The compact
    // store (3.2 GB) fits the 4 GiB limit, the full layout (6.4 GB) does not. The store starts
    // zeroed without being touched and +0 depths are not written, so the refusal at the first 1
    // comes with almost no resident memory (it took 6 s and 3.2 GB when the zeros were written).
    const ProcessResult r = refused_half_zero_zcorn("zeros.grdecl", 1000, 1000, 100, "4");
    if (kMeasureMemory) {
        EXPECT_LT(r.peak_rss_mb, 256 + kBaselineRssMb);  // COORD is 48 MB; the rest is the process
    }
}

// ---- values that would draw blank or lie ------------------------------------------------------

TEST_F(BadInput, HugeCoordinatesAreRefused) {
    for (const std::string zcorn : {"16*1e308", "8*-1e308 8*1e308", "16*1e300"}) {
        SCOPED_TRACE(zcorn);
        std::string text = kTinyGrid;
        text.replace(text.find("16*0 16*1"), 9, zcorn);
        const fs::path grid = file("huge.grdecl", text);
        expect_refused(cutaway({"inspect", grid, "--json"}), {"huge.grdecl", "ZCORN", "coordinate within +-1e9"});
    }
    std::string text = kTinyGrid;
    text.replace(text.find(" 0 0 0 0 0 1"), 12, " 0 0 0 0 0 1e308");
    expect_refused(cutaway({"inspect", file("coord.grdecl", text)}), {"coord.grdecl:4", "COORD", "coordinate within"});
}

TEST_F(BadInput, NonUtf8KeywordIsBadInputBeforeAnyReport) {
    const fs::path grid = file("bytes.grdecl", std::string(kTinyGrid) + "P\xffRO\n 4*0.1 /\n");
    const ProcessResult r = cutaway({"inspect", grid, "--json"});
    expect_refused(r, {"bytes.grdecl:13", "a keyword of ASCII letters and digits", "'P?RO'"});
    EXPECT_TRUE(r.out.empty()) << "half a report: " << r.out;
    expect_refused(cutaway({"render", grid, "--out", out("x.png"), "--stats", out("x.json")}), {"bytes.grdecl:13"});
    expect_no_output();
    // A file name that is not UTF-8 would reach the report's "files" (JSON holds UTF-8 only).
    const fs::path named = file("na\xefve.grdecl", kTinyGrid);
    const ProcessResult n = cutaway({"inspect", named, "--json"});
    expect_refused(n, {"model", "expected UTF-8 text", "na?ve.grdecl"});
    EXPECT_TRUE(n.out.empty()) << n.out;
}

TEST_F(BadInput, WarningsAreCappedAndLongKeywordsTruncated) {
    std::string text = kTinyGrid;
    for (int n = 0; n < 5000; ++n) text += "XUNKNOWN\n 1 2 3 /\n";
    text += std::string(100000, 'K') + "\n 1 /\n";
    const ProcessResult r = cutaway({"inspect", file("noisy.grdecl", text)});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("4901 more warnings not shown"), std::string::npos) << r.out.substr(r.out.size() - 400);
    EXPECT_LT(r.out.size(), std::size_t(20000)) << "warnings not capped";
}

TEST_F(BadInput, LongKeywordIsTruncatedInErrors) {
    const ProcessResult r = cutaway({"inspect", file("long.grdecl", "SPECGRID\n 2 2 1 1 F /\n" + std::string(100000, 'K') + "\n 'x /\n")});
    EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 300);
    EXPECT_LT(r.err.size(), std::size_t(1000)) << "keyword echoed whole";
    EXPECT_NE(r.err.find("KKKK..."), std::string::npos) << r.err;
}

TEST_F(BadInput, NonFiniteSeismicSamplesAreRefused) {
    const fs::path inf_cube = file("inf.sgy", segy_bytes(8, 5, 8, [](int t, int k) {
        return t == 3 && k == 5 ? std::numeric_limits<float>::infinity() : float(k);
    }));
    expect_refused(cutaway({"volume", inf_cube, "--caster", "cpu", "--out", out("v.png")}),
                   {"inf.sgy", "trace 3 sample 5", "expected a finite amplitude", "+inf"});
    const fs::path nan_cube = file("nan.sgy", segy_bytes(8, 5, 8, [](int, int) { return std::numeric_limits<float>::quiet_NaN(); }));
    expect_refused(cutaway({"volume", nan_cube, "--caster", "cpu", "--out", out("v.png")}), {"nan.sgy", "trace 0 sample 0", "NaN"});
    expect_no_output();
}

TEST_F(BadInput, SeismicHeaderFields65535ArePrintedUnsigned) {
    const fs::path samples = file("ns.sgy", segy_bytes(65535, 5, 8, [](int, int k) { return float(k); }));
    const ProcessResult r = cutaway({"volume", samples, "--caster", "cpu", "--out", out("v.png")});
    expect_refused(r, {"ns.sgy", "65535 samples"});
    EXPECT_EQ(r.err.find("-1"), std::string::npos) << r.err;
    const fs::path format = file("format.sgy", segy_bytes(8, 65535, 8, [](int, int k) { return float(k); }));
    const ProcessResult f = cutaway({"volume", format, "--caster", "cpu", "--out", out("v.png")});
    expect_refused(f, {"format.sgy", "'format'", "expected a sample format code 1-16, found 65535 big-endian and 65535 little-endian"});
    expect_no_output();
}

// ---- cases that reach the renderer (EGL on llvmpipe) ------------------------------------------

TEST_F(BadInputGl, FullDiskForTheImageOrTheStatsIsExit2) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(render(grid, {"--no-metrics", "--out", "/dev/full"}), {"/dev/full", "No space left on device"});
    // The image is staged before the stats or the cell ids fail: none of the run's outputs stays.
    expect_refused(render(grid, {"--no-metrics", "--out", out("x.png"), "--stats", "/dev/full"}),
                   {"/dev/full", "No space left on device"});
    expect_refused(render(grid, {"--no-metrics", "--out", out("x.png"), "--stats", out("x.json"), "--cell-ids", "/dev/full"}),
                   {"/dev/full", "No space left on device"});
    expect_refused(render(grid, {"--no-metrics", "--out", out("x.png"), "--stats", "/proc/cutaway-stats.json"}),
                   {"/proc/cutaway-stats.json"});
    expect_no_output();
}

TEST_F(BadInputGl, CameraInsideTheModelIsRefused) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(render(grid, {"--no-metrics", "--camera", "0", "0", "1e-9", "--out", out("x.png")}),
                   {"--camera", "at least the model's radius 1.5", "found 1e-09"});
    expect_no_output();
}

TEST_F(BadInputGl, FramesThatWouldBeBlankAreRefused) {
    // Issue 47: a camera so far that the model covers under a pixel, and primaries-only with no
    // primary, drew an empty frame with exit 0.
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(render(grid, {"--no-metrics", "--camera", "0", "30", "1e9", "--out", out("x.png")}),
                   {"--camera", "the model covers under a pixel", "found 1e+09"});
    expect_refused(render(grid, {"--no-metrics", "--only", "primaries", "--range", "5", "6", "--out", out("x.png")}),
                   {"--only primaries", "no cell of PORO in the primary range [5, 6]"});
    expect_no_output();
    // Both fine where the model covers pixels and has primaries.
    EXPECT_EQ(render(grid, {"--no-metrics", "--camera", "0", "30", "100", "--only", "primaries", "--range", "0.3", "0.4",
                            "--out", out("x.png")}).exit_code, 0);
}

TEST_F(BadInputGl, ModelWithoutHorizontalExtentIsRefused) {
    std::string text = kTinyGrid;
    const std::size_t coord = text.find("COORD\n") + 6, zcorn = text.find("ZCORN");
    std::string pillars;  // all 9 pillars at x = y = 0
    for (int p = 0; p < 9; ++p) pillars += " 0 0 0 0 0 1";
    text.replace(coord, zcorn - coord, pillars + " /\n");
    const fs::path grid = file("point.grdecl", text);
    expect_refused(render(grid, {"--no-metrics", "--out", out("x.png")}), {"point.grdecl", "horizontal extent"});
    expect_no_output();
}

TEST_F(BadInputGl, IntegerPropertySelectsPrimaries) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const ProcessResult r = render(grid, {"--no-metrics", "--property", "FACIES", "--range", "2", "2", "--out", out("x.png")});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("(2 primary cells"), std::string::npos) << r.out;
}

TEST_F(BadInputGl, SecondPropertySelectsWhileTheFirstColours) {
    // FACIES 2 are cells 2 and 4 (Eclipse order); by PORO, the colouring property, [2, 2] holds no cell.
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const ProcessResult r = render(grid, {"--no-metrics", "--property", "PORO", "--select-by", "FACIES", "--range", "2", "2",
                                          "--only", "primaries", "--out", out("x.png"), "--stats", out("x.json"),
                                          "--cell-ids", out("ids.png")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("(2 primary cells"), std::string::npos) << r.out;
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(out("x.json")));
    EXPECT_EQ(stats["property"]["name"], "PORO");
    EXPECT_EQ(stats["property"]["selected_by"], "FACIES");
    EXPECT_EQ(stats["property"]["colour_range"], nlohmann::json::array({0.1f, 0.4f}));
    // The primaries-only frame shows exactly the FACIES 2 cells (id = Eclipse index + 1).
    std::set<std::uint32_t> shown;
    for (const std::uint32_t id : cutaway::pipeline::decode_cell_ids(cutaway::gl::read_png(out("ids.png"))))
        if (id != 0) shown.insert(id);
    EXPECT_EQ(shown, (std::set<std::uint32_t>{2, 4}));
    expect_refused(render(grid, {"--no-metrics", "--select-by", "SATURATION", "--out", out("y.png")}),
                   {"--select-by", "SATURATION", "not in the model"});
}

TEST_F(BadInputGl, MetricWithoutPixelsIsAbsentWithItsReason) {
    // No cell lies in [5, 6]: the primaries-only frame has no primary pixel, so exposure is 0/0.
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const ProcessResult r = render(grid, {"--range", "5", "6", "--out", out("x.png"), "--stats", out("x.json")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(out("x.json"));
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_TRUE(stats["primary_exposure"].is_null()) << stats["primary_exposure"];
    EXPECT_NE(stats.value("primary_exposure_absent", ""), "");
}

}  // namespace
