// Viewer scripts: a full script, every class of error with its location and expected form, files.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <random>
#include <stdexcept>
#include <string>

#include "cpu/test_files.h"
#include "viewer/viewer_script.h"

namespace cutaway::viewer {
namespace {

using Args = std::vector<std::string>;

/// The message parse_viewer_script_text throws for `text` (empty when it parses).
std::string parse_error(const std::string& text) {
    try {
        parse_viewer_script_text(text, "tour.txt");
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "";
}

TEST(ViewerScript, FullScriptParsesToSteps) {
    const std::string text =
        "# a tour of the model\n"
        "\n"
        "camera 35 30 0\n"
        "wait 10   # let the cut settle\n"
        "orbit -15.5 2\n"
        "pan 0.1 -0.2\n"
        "zoom 1.5\n"
        "set --border threshold --ssao off\n"
        "key space\n"
        "Key f12\n"
        "freeze on\n"
        "drag on\n"
        "play off\n"
        "playback none 6\n"
        "ui off\n"
        "   screenshot  out/frame.png\n"
        "quit\n";
    const ViewerScript script = parse_viewer_script_text(text, "tour.txt");
    EXPECT_EQ(script.path, "tour.txt");
    ASSERT_EQ(script.steps.size(), 15u);
    const auto expect_step = [&](std::size_t index, int line, const std::string& action, const Args& args) {
        SCOPED_TRACE(index);
        EXPECT_EQ(script.steps[index].line, line);
        EXPECT_EQ(script.steps[index].action, action);
        EXPECT_EQ(script.steps[index].args, args);
    };
    expect_step(0, 3, "camera", {"35", "30", "0"});
    expect_step(1, 4, "wait", {"10"});
    expect_step(2, 5, "orbit", {"-15.5", "2"});
    expect_step(3, 6, "pan", {"0.1", "-0.2"});
    expect_step(4, 7, "zoom", {"1.5"});
    expect_step(5, 8, "set", {"--border", "threshold", "--ssao", "off"});
    expect_step(6, 9, "key", {"SPACE"});
    expect_step(7, 10, "key", {"F12"});
    expect_step(8, 11, "freeze", {"on"});
    expect_step(9, 12, "drag", {"on"});
    expect_step(10, 13, "play", {"off"});
    expect_step(11, 14, "playback", {"none", "6"});
    expect_step(12, 15, "ui", {"off"});
    expect_step(13, 16, "screenshot", {"out/frame.png"});
    expect_step(14, 17, "quit", {});
    EXPECT_EQ(describe(script, script.steps[5]), "tour.txt:8: set --border threshold --ssao off");
}

TEST(ViewerScript, CommentsAndBlankLinesOnlyGiveNoSteps) {
    EXPECT_TRUE(parse_viewer_script_text("\n   \n# wait 3\n\t# quit\n", "tour.txt").steps.empty());
    EXPECT_TRUE(parse_viewer_script_text("", "tour.txt").steps.empty());
}

TEST(ViewerScript, CrlfLineEndingsParse) {
    const ViewerScript script = parse_viewer_script_text("wait 1\r\nquit\r\n", "tour.txt");
    ASSERT_EQ(script.steps.size(), 2u);
    EXPECT_EQ(script.steps[0].args, Args{"1"});
}

/// A line the parser must refuse, with what the message must say.
struct RefusedCase {
    const char* text;
    int line;
    const char* problem;
    const char* expected;  ///< follows "; expected "
};

// One or more cases per error class: unknown action, argument count, non-number, non-finite number,
// out-of-range value, and words that are not allowed.
const RefusedCase refused_cases[] = {
    {"wait 1\nspin 90\n", 2, "unknown action 'spin'", "one of wait, sleep, orbit, pan, zoom, camera"},
    {"orbit 10\n", 1, "1 argument given", "orbit DAZ DEL"},
    {"zoom 2 3\n", 1, "2 arguments given", "zoom FACTOR"},
    {"camera 1 2\n", 1, "2 arguments given", "camera AZ EL DIST"},
    {"quit now\n", 1, "1 argument given", "quit (no arguments)"},
    {"screenshot a.png b.png\n", 1, "2 arguments given", "screenshot FILE"},
    {"wait\n", 1, "0 arguments given", "wait N"},
    {"set\n", 1, "no option given", "set --OPTION"},
    {"wait 3x\n", 1, "N '3x' is not a whole number", "wait N"},
    {"wait 2.5\n", 1, "N '2.5' is not a whole number", "wait N"},
    {"orbit 10 up\n", 1, "DEL 'up' is not a number", "orbit DAZ DEL"},
    {"pan 0.1x 0\n", 1, "DX '0.1x' is not a number", "pan DX DY"},
    {"zoom nan\n", 1, "FACTOR 'nan' is not finite", "zoom FACTOR"},
    {"orbit inf 0\n", 1, "DAZ 'inf' is not finite", "orbit DAZ DEL"},
    {"camera 1e999 0 0\n", 1, "AZ '1e999' is not finite", "camera AZ EL DIST"},
    {"wait 100001\n", 1, "N 100001 is out of range", "wait N (whole number of frames, 0..100000)"},
    {"wait -1\n", 1, "N -1 is out of range", "wait N"},
    {"pan 0 10.5\n", 1, "DY 10.5 is out of range", "pan DX DY (image heights, -10..10)"},
    {"zoom 0\n", 1, "FACTOR 0 is out of range", "zoom FACTOR (0 < FACTOR <= 100)"},
    {"zoom 101\n", 1, "FACTOR 101 is out of range", "zoom FACTOR"},
    {"camera 0 90 0\n", 1, "EL 90 is out of range", "camera AZ EL DIST"},
    {"camera 0 0 -1\n", 1, "DIST -1 is out of range", "camera AZ EL DIST"},
    {"set border threshold\n", 1, "'border' is not an option", "set --OPTION"},
    {"key Q\n", 1, "unknown key 'Q'", "key NAME (F, H, R, SPACE, F12 or ESCAPE)"},
    {"sleep -1\n", 1, "SECONDS -1 is out of range", "sleep SECONDS (0..3600)"},
    {"freeze yes\n", 1, "'yes' is neither on nor off", "freeze on|off"},
    {"playback fast 4\n", 1, "coherence 'fast' is neither none nor smooth", "playback none|smooth FRAMES_PER_STEP"},
    {"playback smooth 0\n", 1, "FRAMES_PER_STEP 0 is out of range", "playback none|smooth FRAMES_PER_STEP (1..1000)"},
    {"playback smooth 2.5\n", 1, "FRAMES_PER_STEP '2.5' is not a whole number", "playback none|smooth"},
    {"playback smooth\n", 1, "1 argument given", "playback none|smooth"},
    {"volumes add box:0,0,0,0,1,1\n", 1, "box", "volumes add SPEC | clear | save FILE | load FILE"},
    {"volumes drop\n", 1, "'drop' is none of add, clear, save, load", "volumes add SPEC"},
    {"volumes save\n", 1, "save takes one argument", "volumes add SPEC"},
};

TEST(ViewerScript, EveryErrorNamesItsLineAndTheExpectedForm) {
    for (const RefusedCase& refused : refused_cases) {
        SCOPED_TRACE(refused.text);
        const std::string message = parse_error(refused.text);
        EXPECT_EQ(message.rfind("tour.txt:" + std::to_string(refused.line) + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(refused.problem), std::string::npos) << message;
        EXPECT_NE(message.find(std::string("; expected ") + refused.expected), std::string::npos) << message;
    }
}

TEST(ViewerScript, BoundaryValuesAreAccepted) {
    EXPECT_EQ(parse_error("wait 0\nwait 100000\nsleep 0\nsleep 3600\npan -10 10\nzoom 100\ncamera 0 -89 0\ncamera 0 89 5\n"), "");
}

TEST(ViewerScript, HelpListsEveryAction) {
    const std::string help = script_actions_help();
    for (const std::string& action : script_actions())
        EXPECT_NE(help.find("  " + action), std::string::npos) << action;
    EXPECT_EQ(script_actions().size(), 16u);
}

class ViewerScriptFileTest : public ::testing::Test {
protected:
    ViewerScriptFileTest() : dir_("viewer-script-" + std::to_string(std::random_device{}())) {}
    test::ScratchDir dir_;
};

TEST_F(ViewerScriptFileTest, FileParsesWithItsPathInMessages) {
    const auto path = dir_.write("tour.txt", "wait 1\nzoom -2\n");
    try {
        parse_viewer_script(path);
        FAIL() << "bad zoom accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()).rfind(path.string() + ":2: ", 0), 0u) << error.what();
    }
    const auto good = dir_.write("good.txt", "wait 1\n");
    EXPECT_EQ(parse_viewer_script(good).path, good.string());
}

TEST_F(ViewerScriptFileTest, FileOverOneMebibyteIsRefused) {
    const auto path = dir_.write("big.txt", std::string(max_script_bytes + 1, '\n'));
    try {
        parse_viewer_script(path);
        FAIL() << "oversized script accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()), path.string() + ": 1048577 bytes; expected a script of at most 1 MiB");
    }
    EXPECT_NO_THROW(parse_viewer_script(dir_.write("limit.txt", std::string(max_script_bytes, '\n'))));
}

TEST_F(ViewerScriptFileTest, MissingFileCannotBeOpened) {
    const auto path = dir_.path() / "missing.txt";
    try {
        parse_viewer_script(path);
        FAIL() << "missing file accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()), path.string() + ": expected a readable script file, found no such file");
    }
}

TEST_F(ViewerScriptFileTest, FifoIsRefusedWithoutWaitingForAWriter) {
    // Opening a FIFO blocks until a writer opens it: the script is refused before any open.
    const auto path = dir_.path() / "script.fifo";
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    try {
        parse_viewer_script(path);
        FAIL() << "FIFO accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("found a FIFO"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace cutaway::viewer
