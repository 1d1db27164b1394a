#pragma once
// Options of `cutaway view`: the scene options `cutaway render` takes, plus the viewer's own.
#include <string>

#include <CLI/CLI.hpp>

#include "app_core/render_options.h"

namespace cutaway::viewer {

struct ViewerOptions {
    app::RenderOptions render;  ///< model, selection, frame switches, camera, window size
    std::string script;         ///< --script FILE: actions and camera moves (viewer_script.h)
    std::string screenshot;     ///< --screenshot FILE: the last frame drawn, panel included unless --no-ui
    int frames = 0;             ///< stop after this many frames (0: when closed or the script quits)
    bool no_ui = false;         ///< start with the panel and overlay hidden (H shows them)
    std::string stats;          ///< --stats FILE: per-frame loop and stage times, configuration, machine
    float render_scale = 1;     ///< render size / window size
    float interaction_fps = 10; ///< frames per second held while the view moves (0: full size always)
    int timing_window = 31;     ///< frames in the rolling medians
    float ui_scale = 1;         ///< --ui-scale: the panel's and overlays' text and widgets at this multiple
};

void add_viewer_options(CLI::App& command, ViewerOptions& options);

}  // namespace cutaway::viewer
