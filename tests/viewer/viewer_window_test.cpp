// `cutaway view` in a real window under Xvfb (xvfb-run), driven by --script and --screenshot, as a
// user would run it. Every frame comes from the same CutawayRenderer as `cutaway render`, on the
// same Mesa llvmpipe driver, so the viewer's picture of a camera is compared with render's.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "annotation/colour_bar_layout.h"
#include "app_core/model_source.h"
#include "app_core/render_options.h"
#include "cpu/test_files.h"
#include "gl/image.h"

namespace cutaway::test {
namespace {

struct CommandResult {
    int exit_code = -1;
    std::string output;  ///< stdout and stderr
};

/// Runs `command` through the shell, calling `on_line` with each output line as it arrives.
template <typename OnLine>
CommandResult run_command(const std::string& command, OnLine on_line) {
    CommandResult result;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return result;
    std::array<char, 4096> line{};
    while (std::fgets(line.data(), int(line.size()), pipe) != nullptr) {
        result.output += line.data();
        on_line(std::string(line.data()));
    }
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

CommandResult run_command(const std::string& command) {
    return run_command(command, [](const std::string&) {});
}

const std::string cutaway_binary = CUTAWAY_BINARY;
/// A 24-bit screen: the GLX visuals of Xvfb's default 8-bit screen have no OpenGL 4.5 config.
const std::string xvfb = std::string(XVFB_RUN) + " -a -s '-screen 0 1280x1024x24' ";
/// The camera and frame both programs draw (small, so each run takes about a second).
const std::string scene = " preset:petra --size 320 180 --camera 35 30 0 --no-colour-bar ";

std::string view_command(const std::string& arguments) { return xvfb + cutaway_binary + " view" + scene + arguments; }
std::string render_command(const std::string& arguments) {
    return cutaway_binary + " render" + scene + "--no-metrics --warmup 0 --repeat 1 " + arguments;
}

/// Share of pixels whose largest channel difference exceeds `levels`.
double differing_fraction(const gl::RgbaImage& a, const gl::RgbaImage& b, int levels) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    if (a.width != b.width || a.height != b.height) return 1;
    std::size_t differing = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c])) > levels) {
                    ++differing;
                    break;
                }
    return double(differing) / (double(a.width) * a.height);
}

/// Pixels that are not the background colour (the top-left pixel of a frame with nothing there).
std::vector<bool> foreground(const gl::RgbaImage& image) {
    const std::uint8_t* background = image.at(0, 0);
    std::vector<bool> mask(std::size_t(image.width) * image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            mask[std::size_t(y) * image.width + x] = !std::equal(background, background + 3, image.at(x, y));
    return mask;
}

std::size_t count(const std::vector<bool>& mask) { return std::size_t(std::count(mask.begin(), mask.end(), true)); }

class ViewerWindowTest : public ::testing::Test {
protected:
    ScratchDir dir_{"viewer-window-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name())};
    std::string path(const std::string& name) const { return (dir_.path() / name).string(); }
};

TEST_F(ViewerWindowTest, ScreenshotEqualsRenderForTheSameCamera) {
    const CommandResult view = run_command(view_command("--no-ui --frames 2 --screenshot " + path("view.png")));
    ASSERT_EQ(view.exit_code, 0) << view.output;
    const CommandResult render = run_command(render_command("--out " + path("render.png")));
    ASSERT_EQ(render.exit_code, 0) << render.output;
    const gl::RgbaImage viewed = gl::read_png(path("view.png")), rendered = gl::read_png(path("render.png"));
    // Not empty: the model covers a good part of the default framing.
    EXPECT_GT(double(count(foreground(viewed))) / (viewed.width * viewed.height), 0.2);
    // Same renderer, shaders and driver: measured bit-identical. 0.1% of pixels may move by more
    // than 2 levels so a driver that schedules its rasteriser threads differently still passes.
    EXPECT_LE(differing_fraction(viewed, rendered, 2), 0.001);
}

TEST_F(ViewerWindowTest, FramesAreSmallerWhileTheViewMovesAndFullSizeOnceItStops) {
    // --interaction-fps 240: no frame holds that rate, so every decision takes the next smaller
    // size (interaction_resolution.h: starting at half the size, 2 frames measured per size after
    // the first at a new size, which allocates its targets and is not counted).
    std::ofstream script(path("drag.txt"));
    script << "drag on\n";
    for (int turn = 0; turn < 7; ++turn) script << "orbit 10 0\nwait 1\n";
    script << "drag off\nwait 1\nscreenshot " << path("still.png") << "\nquit\n";
    script.close();
    const CommandResult view = run_command(
        view_command("--no-ui --interaction-fps 240 --script " + path("drag.txt") + " --stats " + path("stats.json")));
    ASSERT_EQ(view.exit_code, 0) << view.output;
    std::ifstream stats_file(path("stats.json"));
    const nlohmann::json stats = nlohmann::json::parse(stats_file);
    std::vector<int> moving_widths;
    nlohmann::json last_drawn;
    for (const nlohmann::json& frame : stats["frames"]) {
        if (!frame["rendered"].get<bool>()) continue;
        last_drawn = frame;
        if (frame["view_moving"].get<bool>()) {
            moving_widths.push_back(frame["render_size"][0].get<int>());
            EXPECT_LE(std::abs(frame["render_size"][0].get<int>() * 180 - frame["render_size"][1].get<int>() * 320), 320)
                << "the window's aspect ratio, to a pixel of rounding: " << frame.dump();
        }
    }
    EXPECT_EQ(moving_widths, (std::vector<int>{160, 160, 160, 134, 134, 134, 112})) << "one frame per turn, at 0.5, 0.42, 0.35";
    EXPECT_FALSE(last_drawn["view_moving"].get<bool>());
    EXPECT_EQ(last_drawn["render_size"], nlohmann::json::array({320, 180})) << "the full size once the drag ends";
    EXPECT_EQ(stats["interaction_fps"].get<double>(), 240.0);

    // The still frame after the smaller ones is render's frame of the same camera: the resized
    // targets leave nothing behind (7 turns of 10 degrees from azimuth 35).
    const CommandResult render = run_command(cutaway_binary + " render preset:petra --size 320 180 --camera 105 30 0 "
                                             "--no-colour-bar --no-metrics --warmup 0 --repeat 1 --out " + path("render.png"));
    ASSERT_EQ(render.exit_code, 0) << render.output;
    EXPECT_LE(differing_fraction(gl::read_png(path("still.png")), gl::read_png(path("render.png")), 2), 0.001);
}

TEST_F(ViewerWindowTest, PrimariesAppearWhereRenderPutsThem) {
    std::ofstream(path("only.txt")) << "set --only primaries\nscreenshot " << path("view.png") << "\nquit\n";
    const CommandResult view = run_command(view_command("--no-ui --script " + path("only.txt")));
    ASSERT_EQ(view.exit_code, 0) << view.output;
    const CommandResult render = run_command(render_command("--only primaries --out " + path("render.png")));
    ASSERT_EQ(render.exit_code, 0) << render.output;
    const std::vector<bool> viewed = foreground(gl::read_png(path("view.png")));
    const std::vector<bool> rendered = foreground(gl::read_png(path("render.png")));
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < viewed.size() && i < rendered.size(); ++i) {
        both += viewed[i] && rendered[i];
        either += viewed[i] || rendered[i];
    }
    ASSERT_GT(count(rendered), 200u) << "the 1% PORO primaries of petra cover a few hundred pixels at 320x180";
    // The same pixels, up to the rounding allowance of the test above.
    EXPECT_GE(double(both) / double(either), 0.999);
}

TEST_F(ViewerWindowTest, CutVolumesEditedInTheViewerAreSavedAndRenderedHeadlessAlike) {
    // A box added as the panel's "add box" does (the script's volumes action), saved as the panel's
    // "save" does: `render --cut-volumes` of that file draws the viewer's frame.
    std::ofstream(path("volumes.txt")) << "volumes add box:1000,1000,1900,2500,2600,2150\nvolumes save "
                                       << path("volumes.json") << "\nscreenshot " << path("view.png") << "\nquit\n";
    const CommandResult view = run_command(view_command("--no-ui --script " + path("volumes.txt")));
    ASSERT_EQ(view.exit_code, 0) << view.output;
    std::ifstream saved(path("volumes.json"));
    const nlohmann::json document = nlohmann::json::parse(saved);
    ASSERT_EQ(document["volumes"].size(), 1u);
    EXPECT_EQ(document["volumes"][0]["kind"], "box");
    const CommandResult render = run_command(render_command("--cut-volumes " + path("volumes.json") + " --out " + path("render.png")));
    ASSERT_EQ(render.exit_code, 0) << render.output;
    const CommandResult uncut = run_command(render_command("--out " + path("uncut.png")));
    ASSERT_EQ(uncut.exit_code, 0) << uncut.output;
    const gl::RgbaImage viewed = gl::read_png(path("view.png"));
    // The same rounding allowance as the still-frame test above; the box itself changes far more.
    EXPECT_LE(differing_fraction(viewed, gl::read_png(path("render.png")), 2), 0.001);
    EXPECT_GE(differing_fraction(viewed, gl::read_png(path("uncut.png")), 2), 0.02) << "the box cut nothing";
}

TEST_F(ViewerWindowTest, PanelAndTimingOverlayAreDrawnOverTheFrame) {
    ASSERT_EQ(run_command(view_command("--no-ui --frames 2 --screenshot " + path("plain.png"))).exit_code, 0);
    const CommandResult view = run_command(view_command("--frames 3 --screenshot " + path("ui.png")));
    ASSERT_EQ(view.exit_code, 0) << view.output;
    const gl::RgbaImage plain = gl::read_png(path("plain.png")), ui = gl::read_png(path("ui.png"));
    // The panel covers the top-left corner and the overlay, under it, the bottom-left one (the
    // model is framed right of both): most of a 60x40 patch in each changes (text leaves some
    // background showing through).
    auto changed_share = [&](int x0, int y0) {
        int changed = 0;
        for (int y = y0; y < y0 + 40; ++y)
            for (int x = x0; x < x0 + 60; ++x)
                changed += !std::equal(plain.at(x, y), plain.at(x, y) + 3, ui.at(x, y));
        return changed / 2400.0;
    };
    EXPECT_GT(changed_share(10, 10), 0.5);
    EXPECT_GT(changed_share(10, ui.height - 50), 0.5);
}

TEST_F(ViewerWindowTest, PanelAndTimingOverlayLeaveTheColourBarClear) {
    // The window of paper_figures/viewer_petra.png (16:9, colour bar on) at a smaller size: the
    // overlay is as large as there, so it reaches nearer the bar.
    constexpr int width = 800, height = 450;
    const std::string view = xvfb + cutaway_binary + " view preset:petra --size 800 450 --camera 35 30 0 ";
    ASSERT_EQ(run_command(view + "--no-ui --frames 2 --screenshot " + path("plain.png")).exit_code, 0);
    const CommandResult shown = run_command(view + "--frames 3 --screenshot " + path("ui.png"));
    ASSERT_EQ(shown.exit_code, 0) << shown.output;
    const gl::RgbaImage plain = gl::read_png(path("plain.png")), ui = gl::read_png(path("ui.png"));
    ASSERT_EQ(plain.width, width);
    ASSERT_EQ(plain.height, height);
    // Every pixel the bar may draw (frame, marks, title and tick labels), from the layout the
    // renderer draws it with, for the viewer's default colouring (petra's PORO).
    const app::LoadedModel model = app::load_model({"preset:petra"}, std::size_t(1) << 32, "PORO");
    const app::RenderOptions defaults;  // PORO
    const annotation::PixelRect bar =
        annotation::layout_colour_bar(app::choose_property(model.grid, defaults).colour_bar_label(), width, height).bounds();
    std::size_t covered = 0, changed_elsewhere = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const bool changed = !std::equal(plain.at(x, y), plain.at(x, y) + 3, ui.at(x, y));
            const bool on_bar = float(x) + 2 > bar.x0 && float(x) - 1 < bar.x1 && float(y) + 2 > bar.y0 && float(y) - 1 < bar.y1;
            (on_bar ? covered : changed_elsewhere) += changed;
        }
    // No text over the bar (the overlay's table covered its lowest label before it moved left
    // of the bar's columns), with a pixel of margin; the panel and overlay are drawn elsewhere.
    EXPECT_EQ(covered, 0u) << "bar x " << bar.x0 << ".." << bar.x1 << ", y " << bar.y0 << ".." << bar.y1;
    EXPECT_GT(changed_elsewhere, std::size_t(width) * height / 10);
}

TEST_F(ViewerWindowTest, ScriptDrivesCameraAndEveryControl) {
    std::ofstream(path("tour.txt")) << "# every control the panel has, through the script\n"
                                       "screenshot " << path("start.png") << "\n"
                                       "orbit 40 10\nzoom 0.8\npan 0.05 -0.02\n"
                                       "screenshot " << path("moved.png") << "\n"
                                       "camera 35 30 0\n"
                                       "set --strategy chamfer-34 --border threshold --mean-filter 5 --ssao off\n"
                                       "set --saturation --silhouette --hide-internal-lines --aperture 45 20\n"
                                       "screenshot " << path("settings.png") << "\n"
                                       "key F\norbit 60 0\n"
                                       "screenshot " << path("frozen.png") << "\n"
                                       "freeze off\n"
                                       "screenshot " << path("unfrozen.png") << "\n"
                                       "set --property SWAT --range 0.5 1\nplayback smooth 1\nplay on\nwait 3\nplay off\n"
                                       "screenshot " << path("played.png") << "\n"
                                       "key R\nui on\nkey H\nwait 1\nquit\n";
    const CommandResult view = run_command(view_command("--no-ui --script " + path("tour.txt") + " --stats " + path("stats.json")));
    ASSERT_EQ(view.exit_code, 0) << view.output;
    for (const char* step : {"tour.txt:3: orbit 40 10", "tour.txt:8: set --strategy chamfer-34", "tour.txt:11: key F",
                             "tour.txt:16: set --property SWAT --range 0.5 1", "tour.txt:26: quit"})
        EXPECT_NE(view.output.find(step), std::string::npos) << step << "\n" << view.output;
    const auto image = [&](const char* name) { return gl::read_png(path(name)); };
    // Each group of actions changes the picture (a no-op action would leave it bit-identical).
    EXPECT_GT(differing_fraction(image("start.png"), image("moved.png"), 0), 0.05);
    EXPECT_GT(differing_fraction(image("moved.png"), image("settings.png"), 0), 0.05);
    // Frozen: the cut stays where the first camera put it while the model turns, so releasing it
    // changes the frame of the same camera.
    EXPECT_GT(differing_fraction(image("frozen.png"), image("unfrozen.png"), 0), 0.01);
    EXPECT_GT(differing_fraction(image("unfrozen.png"), image("played.png"), 0), 0.05);

    std::ifstream stats_file(path("stats.json"));
    const nlohmann::json stats = nlohmann::json::parse(stats_file);
    EXPECT_GE(stats["rendered_frames"].get<int>(), 6);
    EXPECT_EQ(stats["configuration"]["strategy"], "chamfer-34");
    EXPECT_EQ(stats["configuration"]["property"], "SWAT");
    EXPECT_GT(stats["configuration"]["step"].get<int>(), 0) << "play advanced the SWAT time step";
    EXPECT_GT(stats["median_stages_ms"]["total"].get<double>(), 0);
}

TEST_F(ViewerWindowTest, PlaybackHoldsEachStepUnderNoneAndMovesBetweenStepsUnderSmooth) {
    // Two frames drawn within the first of 20 frames per step: `none` shows step 0 in both, so
    // they are bit-identical; `smooth` interpolates the values (and paces the primaries) towards
    // step 1, so the second differs. preset:petra's SWAT changes at every cell the flood reaches.
    const auto play = [&](const std::string& coherence) {
        std::ofstream(path(coherence + ".txt")) << "set --property SWAT --range 0.5 1\nplayback " << coherence
                                                << " 20\nplay on\nwait 2\nscreenshot " << path(coherence + "_a.png")
                                                << "\nwait 3\nscreenshot " << path(coherence + "_b.png") << "\nquit\n";
        const CommandResult view = run_command(view_command("--no-ui --script " + path(coherence + ".txt")));
        EXPECT_EQ(view.exit_code, 0) << view.output;
        return differing_fraction(gl::read_png(path(coherence + "_a.png")), gl::read_png(path(coherence + "_b.png")), 0);
    };
    EXPECT_EQ(play("none"), 0.0);
    // A fifth of a step moves the front's colours over a visible share of the frame (measured
    // about 1-10%; any change at all proves the interpolation, 0.1% leaves room for the driver).
    EXPECT_GT(play("smooth"), 0.001);
}

TEST_F(ViewerWindowTest, EditedShadersAreReloadedAndBrokenOnesReported) {
    const std::filesystem::path shaders = dir_.path() / "shaders";
    std::filesystem::copy(CUTAWAY_SOURCE_DIR "/shaders", shaders, std::filesystem::copy_options::recursive);
    const std::filesystem::path composite = shaders / "post" / "composite.comp";
    std::ofstream(path("wait.txt")) << "sleep 6\nquit\n";
    // After the first frame: an edit that compiles, then (a second later) one that does not.
    bool edited = false;
    const CommandResult view = run_command(
        "CUTAWAY_SHADER_DIR=" + shaders.string() + " " + view_command("--no-ui --script " + path("wait.txt")),
        [&](const std::string& line) {
            if (edited || line.find("ready") == std::string::npos) return;
            edited = true;
            std::ofstream(composite, std::ios::app) << "\n// an edit that compiles\n";
            std::thread([composite] {
                std::this_thread::sleep_for(std::chrono::milliseconds(1500));
                std::ofstream(composite, std::ios::app) << "\nthis does not compile\n";
            }).detach();
        });
    ASSERT_EQ(view.exit_code, 0) << view.output;
    EXPECT_NE(view.output.find("shaders reloaded"), std::string::npos) << view.output;
    EXPECT_NE(view.output.find("shader edit not applied"), std::string::npos) << view.output;
    EXPECT_NE(view.output.find("composite.comp"), std::string::npos) << "the compile error names the file\n" << view.output;
}

TEST_F(ViewerWindowTest, BadScriptIsRefusedBeforeAWindowOpens) {
    std::ofstream(path("bad.txt")) << "orbit 10 0\nspin 90\n";
    // No xvfb-run: the script is checked before the window is opened.
    const CommandResult view = run_command(cutaway_binary + " view" + scene + "--script " + path("bad.txt"));
    EXPECT_EQ(view.exit_code, 2) << view.output;
    EXPECT_NE(view.output.find("bad.txt:2: unknown action 'spin'"), std::string::npos) << view.output;
}

TEST_F(ViewerWindowTest, NoDisplayIsAClearErrorWithExitCodeFour) {
    const CommandResult view = run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + cutaway_binary + " view" + scene + "--frames 1");
    EXPECT_EQ(view.exit_code, 4) << view.output;
    EXPECT_NE(view.output.find("DISPLAY"), std::string::npos) << view.output;
    EXPECT_NE(view.output.find("xvfb-run"), std::string::npos) << view.output;
}

TEST_F(ViewerWindowTest, NoOpenGl45IsAClearErrorWithExitCodeFour) {
    // Mesa caps the versions it offers at 3.3 here, as an old driver would.
    const CommandResult view = run_command("MESA_GL_VERSION_OVERRIDE=3.3 " + view_command("--frames 1"));
    EXPECT_EQ(view.exit_code, 4) << view.output;
    EXPECT_NE(view.output.find("OpenGL 4.5 core"), std::string::npos) << view.output;
}

}  // namespace
}  // namespace cutaway::test
