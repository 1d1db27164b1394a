// `--wells` refusals (issue 45), run as a user runs `cutaway render`: unknown well names (the
// message lists the known ones), a missing or malformed wells file, a connection outside the
// grid, values that do not combine: exit 2, one line naming the option or file, nothing written.
#include <gtest/gtest.h>

#include "bad_input_fixture.h"

namespace {

using namespace cutaway::testing;
namespace fs = std::filesystem;

// Two wells on kTinyGrid's 2 x 2 x 1 cells.
constexpr const char* kTwoWells = "WELSPECS\n 'P1' 'G' 1 1 1* 'OIL' /\n 'I1' 'G' 2 2 1* 'WATER' /\n/\n"
                                  "COMPDAT\n 'P1' 2* 1 1 'OPEN' /\n 'I1' 2* 1 1 'OPEN' /\n/\n";

TEST_F(BadInput, WellsThatAreNotThereAreRefusedNamingTheKnownOnes) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const fs::path wells = file("wells.inc", kTwoWells);
    expect_refused(cutaway({"render", grid, "--wells", wells, "--wells", "NOPE", "--out", out("x.png")}),
                   {"--wells", "NOPE", "P1, I1"});
    expect_no_output();
    // A model without a restart holds no wells: a FILE must name them.
    expect_refused(cutaway({"render", grid, "--wells", "all", "--out", out("x.png")}), {"--wells", "--wells FILE"});
    expect_no_output();
}

TEST_F(BadInput, MissingOrMalformedWellsFilesAreRefusedNamingTheFile) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(cutaway({"render", grid, "--wells", (scratch_ / "missing.DATA").string(), "--out", out("x.png")}),
                   {"missing.DATA", "no such file"});
    expect_no_output();
    const fs::path malformed = file("malformed.inc", "WELSPECS\n 'P1' 'G' one 1 /\n/\n");
    expect_refused(cutaway({"render", grid, "--wells", malformed, "--out", out("x.png")}), {"malformed.inc", "WELSPECS"});
    expect_no_output();
    const fs::path no_wells = file("no_wells.inc", "PORO\n 4*0.2 /\n");
    expect_refused(cutaway({"render", grid, "--wells", no_wells, "--out", out("x.png")}), {"no_wells.inc", "WELSPECS"});
    expect_no_output();
    const fs::path undefined = file("undefined.inc", "WELSPECS\n 'P1' 'G' 1 1 /\n/\nCOMPDAT\n 'X9' 2* 1 1 /\n/\n");
    expect_refused(cutaway({"render", grid, "--wells", undefined, "--out", out("x.png")}), {"undefined.inc", "COMPDAT", "X9"});
    expect_no_output();
}

TEST_F(BadInput, ConnectionsOutsideTheGridAreRefused) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    const fs::path deep = file("deep.inc", "WELSPECS\n 'P1' 'G' 1 1 /\n/\nCOMPDAT\n 'P1' 2* 1 2 /\n/\n");
    expect_refused(cutaway({"render", grid, "--wells", deep, "--out", out("x.png")}), {"deep.inc", "P1", "(1, 1, 2)"});
    expect_no_output();
    const fs::path far = file("far.inc", "WELSPECS\n 'P1' 'G' 3 1 /\n/\nCOMPDAT\n 'P1' 2* 1 1 /\n/\n");
    expect_refused(cutaway({"render", grid, "--wells", far, "--out", out("x.png")}), {"far.inc", "P1", "wellhead"});
    expect_no_output();
}

TEST_F(BadInput, WellsValuesThatDoNotCombineAreRefusedBeforeReading) {
    const fs::path grid = file("tiny.grdecl", kTinyGrid);
    expect_refused(cutaway({"render", grid, "--wells", "a.DATA", "--wells", "b.DATA", "--out", out("x.png")}),
                   {"--wells", "at most one FILE"});
    expect_refused(cutaway({"render", grid, "--wells", "all", "--wells", "none", "--out", out("x.png")}),
                   {"--wells", "one selection"});
    expect_refused(cutaway({"render", grid, "--wells", "P1,,I1", "--out", out("x.png")}), {"--wells", "empty name"});
    expect_refused(cutaway({"render", grid, "--well-radius", "-1", "--out", out("x.png")}), {"--well-radius"});
    expect_no_output();
}

}  // namespace
