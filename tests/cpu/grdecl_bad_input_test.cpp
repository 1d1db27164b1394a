// Every kind of malformed input ends in one GrdeclError naming file, line, keyword, what was
// expected and what was found; none crashes, hangs or allocates beyond the memory limit.
#include <gtest/gtest.h>

#include "grid/grdecl_reader.h"
#include "test_files.h"

using namespace cutaway::grid;
using cutaway::test::ScratchDir;

namespace {

const std::string header = "SPECGRID\n 1 1 1 /\n";
const std::string coord = "COORD\n 0 0 0 0 0 1  1 0 0 1 0 1  0 1 0 0 1 1  1 1 0 1 1 1 /\n";
const std::string zcorn = "ZCORN\n 4*0 4*1 /\n";

struct Expectation {
    int line;
    std::string keyword;
    std::string expected;  // substring
    std::string found;     // substring
};

GrdeclErrorInfo error_of(const std::string& text, GrdeclReadOptions options = {}) {
    GrdeclReader reader(options);
    try {
        reader.read_text(text, "case.grdecl");
        (void)reader.finish();
    } catch (const GrdeclError& error) {
        return error.info();
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return {};
}

void expect_error(const std::string& text, const Expectation& e, GrdeclReadOptions options = {}) {
    const GrdeclErrorInfo info = error_of(text, options);
    EXPECT_EQ(info.file, "case.grdecl");
    EXPECT_EQ(info.line, e.line);
    EXPECT_EQ(info.keyword, e.keyword);
    EXPECT_NE(info.expected.find(e.expected), std::string::npos) << "expected: " << info.expected;
    EXPECT_NE(info.found.find(e.found), std::string::npos) << "found: " << info.found;
}

}  // namespace

TEST(GrdeclBadInput, ValidBaseCaseLoads) {
    GrdeclReader reader;
    reader.read_text(header + coord + zcorn, "case.grdecl");
    EXPECT_EQ(reader.finish().active_count(), 1u);
}

TEST(GrdeclBadInput, TruncatedArray) {
    expect_error(header + coord + "ZCORN\n 4*0 3*1 /\n", {6, "ZCORN", "8 values", "7"});
}

TEST(GrdeclBadInput, TooManyValues) {
    expect_error(header + coord + "ZCORN\n 4*0 4*1\n 2 /\n", {7, "ZCORN", "8 values", "at least 9"});
}

TEST(GrdeclBadInput, NonNumericToken) {
    expect_error(header + "COORD\n 0 0 0 0 0 1\n 1 0 abc 1 0 1 /\n", {5, "COORD", "a number", "'abc'"});
}

TEST(GrdeclBadInput, NegativeOrZeroDimensions) {
    expect_error("SPECGRID\n 4 -2 1 /\n", {2, "SPECGRID", "positive integer NY", "'-2'"});
    expect_error("DIMENS\n 0 1 1 /\n", {2, "DIMENS", "positive integer NX", "'0'"});
    expect_error("SPECGRID\n 1 1 /\n", {2, "SPECGRID", "NX NY NZ", "2 items"});
}

TEST(GrdeclBadInput, AbsurdDimensionsAreRefusedBeforeAllocating) {
    // 1e5 x 1e5 x 1e3 cells would need ~3e14 bytes: refused at SPECGRID, nothing allocated.
    expect_error("SPECGRID\n 100000 100000 1000 /\n", {1, "SPECGRID", "memory limit", "100000 x 100000 x 1000"});
    GrdeclReadOptions small;
    small.memory_limit_bytes = 1 << 20;
    expect_error("SPECGRID\n 100 100 100 /\n", {1, "SPECGRID", "memory limit", "100 x 100 x 100"}, small);
}

TEST(GrdeclBadInput, NanAndInfinityCoordinates) {
    expect_error(header + "COORD\n 0 0 nan 0 0 1 /\n", {4, "COORD", "a finite number", "'nan'"});
    expect_error(header + coord + "ZCORN\n 4*0 3*1 inf /\n", {6, "ZCORN", "a finite number", "'inf'"});
    expect_error("MAPAXES\n 0 1 0 0 1 -inf /\n", {2, "MAPAXES", "a finite number", "'-inf'"});
}

TEST(GrdeclBadInput, MissingSpecgrid) {
    expect_error(coord, {1, "COORD", "SPECGRID or DIMENS before COORD", "no grid dimensions"});
    expect_error("PORO\n 0.1 /\n", {1, "PORO", "SPECGRID or DIMENS before PORO", "no grid dimensions"});
    expect_error("MAPUNITS\n 'METRES' /\n", {0, "SPECGRID", "SPECGRID or DIMENS", "none"});
}

TEST(GrdeclBadInput, MissingCoordOrZcorn) {
    expect_error(header + zcorn, {0, "COORD", "COORD", "none"});
    expect_error(header + coord, {0, "ZCORN", "ZCORN", "none"});
}

TEST(GrdeclBadInput, MissingTerminator) {
    expect_error(header + coord + "ZCORN\n 4*0 4*1\n", {7, "ZCORN", "'/' terminator", "end of file"});
    expect_error(header + "COORD\n 0 0 0 0 0 1\nZCORN\n 8*0 /\n", {5, "COORD", "'/' terminator", "keyword ZCORN"});
}

TEST(GrdeclBadInput, BadRepeatsAndDefaults) {
    expect_error(header + coord + "ZCORN\n 0*0 8*1 /\n", {6, "ZCORN", "N a positive integer", "'0*0'"});
    expect_error(header + coord + "ZCORN\n x*2 /\n", {6, "ZCORN", "N a positive integer", "'x*2'"});
    expect_error(header + coord + "ZCORN\n 8* /\n", {6, "ZCORN", "defaults", "'8*'"});
}

TEST(GrdeclBadInput, ActnumOutOfRange) {
    expect_error(header + coord + zcorn + "ACTNUM\n 5 /\n", {8, "ACTNUM", "0..3", "'5'"});
    expect_error(header + coord + zcorn + "ACTNUM\n 0.5 /\n", {8, "ACTNUM", "an integer", "'0.5'"});
}

TEST(GrdeclBadInput, SecondGridKeywordAndConflictingDimensions) {
    expect_error(header + coord + coord, {5, "COORD", "one COORD", "a second"});
    expect_error(header + "SPECGRID\n 2 1 1 /\n", {3, "SPECGRID", "1 x 1 x 1", "2 x 1 x 1"});
}

TEST(GrdeclBadInput, UnterminatedQuoteAndStrayValues) {
    expect_error("MAPUNITS\n 'METRES /\n", {2, "MAPUNITS", "closing quote", "'METRES /'"});
    expect_error("12 13\n", {1, "", "a keyword", "'12'"});
}

TEST(GrdeclBadInput, UnsupportedSpecgridOptions) {
    expect_error("SPECGRID\n 1 1 1 2 F /\n", {2, "SPECGRID", "NUMRES 1", "'2'"});
    expect_error("SPECGRID\n 1 1 1 1 T /\n", {2, "SPECGRID", "COORDTYPE F", "'T'"});
}

TEST(GrdeclBadInput, MissingFile) {
    try {
        (void)load_grdecl({"/nonexistent/model.grdecl"});
        FAIL();
    } catch (const GrdeclError& error) {
        EXPECT_EQ(error.info().file, "/nonexistent/model.grdecl");
        EXPECT_NE(error.info().found.find("no such file"), std::string::npos);
    }
}

TEST(GrdeclBadInput, MissingIncludeNamesTheIncludingFileAndLine) {
    ScratchDir dir("missing-include");
    const auto main = dir.write("main.grdecl", header + "\nINCLUDE\n 'nope.inc' /\n");
    try {
        (void)load_grdecl({main});
        FAIL();
    } catch (const GrdeclError& error) {
        EXPECT_EQ(error.info().file, main.string());
        EXPECT_EQ(error.info().line, 5);  // the line of the file name
        EXPECT_EQ(error.info().keyword, "INCLUDE");
        EXPECT_NE(error.info().expected.find("nope.inc"), std::string::npos);
    }
}

TEST(GrdeclBadInput, IncludeLoopIsDetected) {
    ScratchDir dir("include-loop");
    dir.write("a.inc", "INCLUDE\n 'b.inc' /\n");
    dir.write("b.inc", "INCLUDE\n 'a.inc' /\n");
    const auto main = dir.write("main.grdecl", "INCLUDE\n 'a.inc' /\n");
    try {
        (void)load_grdecl({main});
        FAIL();
    } catch (const GrdeclError& error) {
        EXPECT_NE(error.info().found.find("loop"), std::string::npos) << error.what();
        EXPECT_NE(error.info().found.find("a.inc"), std::string::npos) << error.what();
        EXPECT_EQ(error.info().keyword, "INCLUDE");
    }
}

TEST(GrdeclBadInput, SelfIncludeIsALoopToo) {
    ScratchDir dir("self-include");
    const auto main = dir.write("main.grdecl", "INCLUDE\n 'main.grdecl' /\n");
    EXPECT_THROW((void)load_grdecl({main}), GrdeclError);
}

TEST(GrdeclBadInput, IncludeIsRefusedWhenDisabled) {
    GrdeclReadOptions options;
    options.allow_include = false;
    expect_error("INCLUDE\n 'x.inc' /\n", {2, "INCLUDE", "disabled", "'x.inc'"}, options);
}

TEST(GrdeclBadInput, FuzzRegressionsFailCleanlyOrLoad) {
    // Every input the fuzzer ever crashed on: now a GrdeclError or a grid, nothing else.
    const auto dir = std::filesystem::path(CUTAWAY_SOURCE_DIR) / "tests/fuzz/regressions";
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".grdecl") continue;
        SCOPED_TRACE(entry.path().string());
        GrdeclReadOptions options;
        options.memory_limit_bytes = std::size_t(64) << 20;
        options.allow_include = false;
        try {
            (void)load_grdecl({entry.path()}, options);
        } catch (const GrdeclError&) {
        }
    }
}
