#pragma once
// `cutaway view`: a window showing the cutaway of a model, driven by mouse, keys, the control
// panel or a script. Each frame is drawn by the same CutawayRenderer as `cutaway render`; the
// viewer only decides when to draw (something changed) and blits the result to the window.
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "gl/glfw_window.h"
#include "gl/shader_library.h"
#include "viewer/control_panel.h"
#include "viewer/frame_timings.h"
#include "viewer/imgui_session.h"
#include "viewer/interaction_resolution.h"
#include "viewer/script_runner.h"
#include "viewer/shader_watcher.h"
#include "viewer/viewer_options.h"
#include "viewer/viewer_scene.h"
#include "viewer/viewer_state.h"

namespace cutaway::viewer {

class ViewerApp {
public:
    /// Opens the window (gl::GlError when there is no display or GL 4.5), parses the script and
    /// loads the model (std::invalid_argument / GrdeclError for bad ones).
    explicit ViewerApp(ViewerOptions options);
    /// Runs until the window closes, the script quits or --frames are drawn; returns the exit code.
    int run();

private:
    /// One pass of the loop; false when the viewer should stop after it.
    bool frame(bool last_frame_due);
    unsigned handle_keys();
    unsigned press_key(const std::string& name);
    /// `volumes add SPEC | clear | save FILE | load FILE` (script and panel): the Change bits.
    /// Throws std::invalid_argument (a bad spec or file) and io errors.
    unsigned volume_command(const std::vector<std::string>& args);
    /// volume_command with its errors shown in the panel instead.
    unsigned panel_volume_command(const std::vector<std::string>& args);
    unsigned mouse_camera();
    bool run_step(const ScriptStep& step, unsigned& changes);
    unsigned advance_play();
    /// The fractional report step shown: the played frame's while playing, else the options' step.
    double shown_time_step() const;
    void apply(unsigned changes);
    /// Whether the view moves now (a drag, the wheel in the last moments, a script's drag); a
    /// change of that re-renders (smaller as it starts, the full size as it stops).
    unsigned track_movement();
    /// Whether frames are drawn at the interaction resolution now.
    bool drawing_smaller() const { return view_moving_ && state_.interaction_fps > 0; }
    void reload_shaders_if_edited();
    pipeline::Camera camera_for(const pipeline::OrbitPose& pose) const;
    void sync_freeze();
    void write_screenshot(const std::string& path) const;
    std::string next_screenshot_name();
    void write_stats() const;
    /// The render size: the window's at the render scale, times the interaction factor while the
    /// view moves.
    int render_width() const;
    int render_height() const;
    float render_factor() const;

    ViewerOptions options_;
    ViewerState state_;
    pipeline::OrbitPose initial_pose_;
    std::optional<ScriptRunner> script_;
    gl::GlfwWindow window_;
    std::deque<int> pressed_keys_;  ///< GLFW key codes queued by the key callback
    ImGuiSession imgui_;
    gl::ShaderLibrary shaders_;
    ShaderWatcher shader_watcher_;
    std::chrono::steady_clock::time_point last_shader_scan_{};
    std::unique_ptr<ViewerScene> scene_;
    std::unique_ptr<StepPlayer> player_;   ///< while playing
    double played_time_step_ = 0;          ///< the played frame's fractional report step
    pipeline::FrameSettings settings_;
    FrameTimings timings_;
    PanelInfo info_;
    bool needs_render_ = true;
    InteractionResolution interaction_;
    bool mouse_dragging_ = false;  ///< a button held and moved over the frame (not the panel)
    std::chrono::steady_clock::time_point last_wheel_{};
    bool view_moving_ = false;
    bool quit_ = false;
    std::string screenshot_due_;    ///< path to write once this frame is drawn
    int window_fb_width_ = 0, window_fb_height_ = 0;
    long frame_index_ = 0;
    int screenshots_taken_ = 0;
};

}  // namespace cutaway::viewer
