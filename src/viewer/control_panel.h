#pragma once
// The viewer's control panel (Dear ImGui): property and primary range over its histogram, time
// step, play with its coherence and frames per step, apertures, strategy, border mode, mean filter, SSAO, saturation, silhouette,
// internal lines, freeze view, render scale, camera reset and screenshot.
#include <string>
#include <vector>

#include "viewer/viewer_scene.h"
#include "viewer/viewer_state.h"

namespace cutaway::viewer {

/// What the panel shows besides the state.
struct PanelInfo {
    std::string gl_renderer;
    int render_width = 0, render_height = 0;
    std::string message;  ///< last error or notice (shader reload, bad range), shown in colour
    std::string step_caption;  ///< property, date and fractional step shown (empty: a static property)
};

/// Buttons that ask the viewer to do something rather than change the state.
struct PanelRequests {
    bool screenshot = false;
    bool reset_camera = false;
    std::vector<std::string> volumes;  ///< a `volumes` command (add SPEC, clear, save FILE, load FILE), or empty
};

/// Draws the panel; edits `state` and returns the Change bits of what was edited.
unsigned draw_control_panel(ViewerState& state, const ViewerScene& scene, const PanelInfo& info,
                            PanelRequests& requests);

}  // namespace cutaway::viewer
