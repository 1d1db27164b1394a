#pragma once
// Everything the viewer's controls change. Selection and frame switches are the very options
// `cutaway render` takes (RenderOptions), so a view can be reproduced headless with the same flags.
#include <optional>
#include <string>
#include <vector>

#include "app_core/render_options.h"
#include "cutaway/camera.h"
#include "volumes/cut_volume.h"

namespace cutaway::viewer {

struct ViewerState {
    app::RenderOptions options;                    ///< selection and frame switches, window size
    pipeline::OrbitPose pose;                      ///< the model camera
    std::optional<pipeline::OrbitPose> frozen_pose;  ///< freeze view: the cut camera's pose
    bool playing = false;                          ///< advance the time step of a dynamic property
    int frames_per_step = 8;                       ///< frames from one report step to the next while playing
    std::string coherence = "smooth";              ///< how play moves between steps (temporal::Coherence by name)
    bool ui_visible = true;                        ///< control panel and timing overlay
    /// Share of the window's width the control panel covers from its left edge (0: hidden or
    /// collapsed): the model is framed to the right of it.
    float panel_share = 0;
    /// The timing overlay's size last frame (pixels): it stands under the panel, which leaves it
    /// this height, and the model is framed right of whichever of the two is wider.
    float overlay_width = 0;
    float overlay_height = 0;
    float render_scale = 1;                        ///< render size / window framebuffer size
    /// While the view moves, frames are drawn smaller to hold this many per second (interaction_
    /// resolution.h); the full size once it stops. 0: always the full size.
    float interaction_fps = 10;
    bool script_drag = false;                      ///< a script's `drag on`: the view is moving
    /// The cut volumes being edited (the panel's and a script's `volumes`); taken by the scene on
    /// change_cut_volumes. Loaded from the scene at start.
    std::vector<volumes::CutVolume> cut_volumes;
    std::string cut_volumes_file = "cut_volumes.json";  ///< where the panel saves and loads them
};

/// What a change to the state invalidates, from cheapest to dearest.
enum Change : unsigned {
    change_none = 0,
    change_frame = 1,      ///< re-render with the new settings or camera
    change_selection = 2,  ///< property, step or range: new colouring and primaries
    change_size = 4,       ///< render size: the renderer's per-pixel targets are reallocated
    change_cut_volumes = 8,  ///< the cut volumes: their meshes built and uploaded again
};

}  // namespace cutaway::viewer
