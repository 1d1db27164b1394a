#pragma once
// Options of `cutaway animate`: render's scene options (model, selection, frame, camera, size)
// plus the animation's steps, timing, coherence, orbit and outputs.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app_core/render_options.h"

namespace cutaway::app {

struct AnimateOptions {
    RenderOptions scene;             ///< --property, --range, frame switches, --camera, --size, ...
    std::string out;                 ///< the MP4
    std::string stats;               ///< stats.json (empty: none)
    std::vector<int> steps;          ///< FIRST LAST report steps (0-based, inclusive); empty: all
    int frames_per_step = 4;         ///< frames from one report step to the next
    double fps = 12;                 ///< playback frames per second
    std::string coherence = "smooth";
    /// --hysteresis: a primary stays primary until its value leaves the range widened by this
    /// fraction of the property's span over the animated steps on each side (smooth only).
    double hysteresis = 0.02;
    double orbit_deg = 0;            ///< azimuth turned over the whole animation, degrees
    std::string frames_dir;          ///< PNG frames (empty: none)
    bool metrics = true;             ///< primary_exposure and cut_flicker per frame
    int crf = 20;                    ///< x264 constant rate factor
    bool time_against_render = false;  ///< draw each frame again as `render` does, timed (render_ms)
};

/// Registers every option of `cutaway animate` on `command`.
void add_animate_options(CLI::App& command, AnimateOptions& options);

/// Every effective option, for stats.json: render's (scene.describe()) plus the animation's.
nlohmann::json describe(const AnimateOptions& options);

}  // namespace cutaway::app
