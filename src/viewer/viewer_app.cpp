#include "viewer/viewer_app.h"

#include <epoxy/gl.h>
// epoxy first: GLFW must not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "app_core/run_context.h"
#include "app_core/run_context_json.h"
#include "cutaway/renderer_readback.h"
#include "eclipse/step_clock.h"
#include "gl/gl_error.h"
#include "gl/image.h"
#include "io/output_batch.h"
#include "viewer/camera_controller.h"
#include "viewer/option_tokens.h"
#include "viewer/step_overlay.h"
#include "viewer/timing_overlay.h"
#include "volumes/cut_volume_json.h"
#include "volumes/cut_volume_spec.h"

namespace cutaway::viewer {
namespace {

using Clock = std::chrono::steady_clock;

/// The wheel counts as moving the view for this long after its last step: a flick of the wheel
/// gives several steps a few frames apart.
constexpr std::chrono::milliseconds wheel_moves_for(400);

double milliseconds_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// The viewer's key names (the script's `key NAME`) of the GLFW keys it binds.
std::string key_name(int key) {
    switch (key) {
        case GLFW_KEY_F: return "F";
        case GLFW_KEY_H: return "H";
        case GLFW_KEY_R: return "R";
        case GLFW_KEY_SPACE: return "SPACE";
        case GLFW_KEY_F12: return "F12";
        case GLFW_KEY_ESCAPE: return "ESCAPE";
        default: return "";
    }
}

/// Queues pressed keys on `keys` (through the window's user pointer) before ImGui installs its
/// own callbacks, which chain to this one.
gl::GlfwWindow& install_key_queue(gl::GlfwWindow& window, std::deque<int>& keys) {
    glfwSetWindowUserPointer(window.handle(), &keys);
    glfwSetKeyCallback(window.handle(), [](GLFWwindow* handle, int key, int, int action, int) {
        if (action == GLFW_PRESS) static_cast<std::deque<int>*>(glfwGetWindowUserPointer(handle))->push_back(key);
    });
    return window;
}

gl::WindowOptions window_options(const ViewerOptions& options) {
    gl::WindowOptions window;
    window.width = options.render.width;
    window.height = options.render.height;
    window.title = "cutaway view: " + (options.render.model.empty() ? std::string() : options.render.model.front());
#ifndef NDEBUG
    window.debug_output = true;
#endif
    return window;
}

bool on_off(const std::string& value) { return value == "on"; }

}  // namespace

ViewerApp::ViewerApp(ViewerOptions options)
    : options_(std::move(options)),
      script_(options_.script.empty() ? std::nullopt : std::optional<ScriptRunner>(parse_viewer_script(options_.script))),
      window_(window_options(options_)),
      imgui_(install_key_queue(window_, pressed_keys_), options_.ui_scale),
      shaders_(gl::ShaderLibrary::default_root()),
      shader_watcher_(shaders_.root()),
      timings_(std::size_t(options_.timing_window)) {
    state_.options = options_.render;
    state_.pose = options_.render.camera_pose();
    initial_pose_ = state_.pose;
    state_.frozen_pose = options_.render.freeze_pose;
    state_.ui_visible = !options_.no_ui;
    state_.render_scale = options_.render_scale;
    state_.interaction_fps = options_.interaction_fps;
    settings_ = state_.options.frame_settings();
    info_.gl_renderer = gl::gl_renderer() + " (" + window_.platform() + ")";
    window_fb_width_ = window_.framebuffer_width();
    window_fb_height_ = window_.framebuffer_height();
    // An INCLUDE the screenshot or the stats would overwrite is refused before it is read.
    const std::vector<io::NamedFile> outputs{{"--screenshot", options_.screenshot}, {"--stats", options_.stats}};
    scene_ = std::make_unique<ViewerScene>(app::load_model(options_.render.model, options_.render.model_memory_limit_bytes(),
                                                           std::nullopt, outputs),
                                           shaders_, state_.options, render_width(), render_height());
    if (scene_->primary_count() == 0)
        info_.message = "no cell lies in the primary range; showing the context only";
    state_.cut_volumes = scene_->cut_volumes();
}

unsigned ViewerApp::volume_command(const std::vector<std::string>& args) {
    const std::string& verb = args.at(0);
    if (verb == "add") {
        state_.cut_volumes.push_back(volumes::parse_cut_volume_spec(args.at(1)));
    } else if (verb == "clear") {
        state_.cut_volumes.clear();
    } else if (verb == "save") {
        io::write_file(args.at(1), volumes::cut_volumes_document(state_.cut_volumes).dump(2) + '\n');
        info_.message = "cut volumes saved to " + args.at(1);
        return change_none;
    } else if (verb == "load") {
        state_.cut_volumes = volumes::read_cut_volumes_file(args.at(1), state_.options.model_memory_limit_bytes());
    } else {
        throw std::invalid_argument("volumes " + verb + ": expected add SPEC, clear, save FILE or load FILE");
    }
    return change_cut_volumes;
}

float ViewerApp::render_factor() const {
    return state_.render_scale * (drawing_smaller() ? interaction_.factor() : 1.0f);
}
int ViewerApp::render_width() const { return std::max(1, int(std::lround(window_fb_width_ * render_factor()))); }
int ViewerApp::render_height() const { return std::max(1, int(std::lround(window_fb_height_ * render_factor()))); }

pipeline::Camera ViewerApp::camera_for(const pipeline::OrbitPose& pose) const {
    const pipeline::CutawayRenderer& renderer = scene_->renderer();
    // The panel covers the image's left columns: the model is framed right of it.
    const float panel_px = state_.ui_visible ? state_.panel_share * float(render_width()) : 0.0f;
    return pipeline::make_orbit_camera(renderer.frame(), pose, render_width(), render_height(),
                                       renderer.status(settings_).colour_bar_reserved_width, panel_px);
}

int ViewerApp::run() {
    std::cout << "cutaway view: " << scene_->description() << ", " << scene_->primary_count() << " primary cells, "
              << info_.gl_renderer << '\n' << std::flush;
    bool running = true;
    while (running) {
        const bool last_frame_due = options_.frames > 0 && frame_index_ + 1 >= options_.frames;
        running = frame(last_frame_due) && !last_frame_due;
    }
    if (!options_.stats.empty()) write_stats();
    return 0;
}

bool ViewerApp::frame(bool last_frame_due) {
    const bool waiting_is_fine = !script_ && options_.frames == 0 && !needs_render_ && !state_.playing;
    if (waiting_is_fine) glfwWaitEventsTimeout(0.25);  // idle: no busy loop, still polls shader edits
    else glfwPollEvents();
    const Clock::time_point started = Clock::now();

    reload_shaders_if_edited();
    unsigned changes = change_none;
    if (script_ && frame_index_ > 0)  // the script starts once the first frame is on screen
        script_->run_frame([&](const ScriptStep& step) { return run_step(step, changes); });
    imgui_.begin_frame();
    changes |= handle_keys() | mouse_camera() | advance_play();
    changes |= track_movement();
    PanelRequests requests;
    if (state_.ui_visible) {
        info_.render_width = render_width();
        info_.render_height = render_height();
        info_.step_caption = scene_->step_count() == 0
                                 ? std::string()
                                 : eclipse::step_caption(scene_->property().name,
                                                         eclipse::date_at(scene_->report_steps(), shown_time_step()),
                                                         shown_time_step(), scene_->step_count());
        changes |= draw_control_panel(state_, *scene_, info_, requests);
        const pipeline::CutawayRenderer& renderer = scene_->renderer();
        const float colour_bar_share = renderer.status(settings_).colour_bar_reserved_width / float(renderer.status().width);
        draw_step_overlay(info_.step_caption, colour_bar_share);
        const ImVec2 overlay = draw_timing_overlay(timings_);
        state_.overlay_width = overlay.x;
        state_.overlay_height = overlay.y;
    }
    if (requests.reset_camera) changes |= press_key("R");
    if (!requests.volumes.empty()) changes |= panel_volume_command(requests.volumes);
    if (requests.screenshot) changes |= press_key("F12");
    if (window_.framebuffer_width() != window_fb_width_ || window_.framebuffer_height() != window_fb_height_) {
        window_fb_width_ = window_.framebuffer_width();
        window_fb_height_ = window_.framebuffer_height();
        changes |= change_size;
    }
    apply(changes);

    LoopPass pass;
    bool resized = false;
    if (needs_render_ && window_fb_width_ > 0 && window_fb_height_ > 0) {
        // A new size reallocates only the per-pixel targets: the model's buffers and programs stay.
        resized = render_width() != scene_->renderer().status().width || render_height() != scene_->renderer().status().height;
        scene_->renderer().resize(render_width(), render_height());
        sync_freeze();
        timings_.add_render(scene_->renderer().render(settings_, camera_for(state_.pose)));
        needs_render_ = false;
        pass = {0, true, render_width(), render_height(), drawing_smaller()};
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, window_fb_width_, window_fb_height_);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    pipeline::FrameReadback(scene_->renderer()).present(0, 0, 0, window_fb_width_, window_fb_height_);
    imgui_.end_frame(state_.ui_visible);

    const bool stopping = quit_ || window_.close_requested() || last_frame_due;
    if (!screenshot_due_.empty()) write_screenshot(std::exchange(screenshot_due_, {}));
    if (stopping && !options_.screenshot.empty()) write_screenshot(options_.screenshot);
    window_.swap_buffers();
    pass.loop_ms = milliseconds_since(started);
    timings_.add_loop(pass);
    // Frame 0 compiles the programs and the first frame of a size allocates its targets: their
    // times say nothing about the size (on petra the first 640 x 360 frame took far longer than the next).
    if (pass.view_moving && !resized && frame_index_ > 0) interaction_.frame_drawn(pass.loop_ms, state_.interaction_fps);
    if (frame_index_ == 0) std::cout << "cutaway view: ready (first frame drawn)\n" << std::flush;
    ++frame_index_;
    return !stopping;
}

unsigned ViewerApp::handle_keys() {
    unsigned changes = change_none;
    const bool typing = ImGui::GetIO().WantCaptureKeyboard;
    while (!pressed_keys_.empty()) {
        const std::string name = key_name(pressed_keys_.front());
        pressed_keys_.pop_front();
        if (!name.empty() && !typing) changes |= press_key(name);
    }
    return changes;
}

unsigned ViewerApp::panel_volume_command(const std::vector<std::string>& args) {
    try {
        return volume_command(args);
    } catch (const std::exception& error) {  // a file that cannot be read or written: said in the panel
        info_.message = error.what();
        return change_none;
    }
}

unsigned ViewerApp::press_key(const std::string& name) {
    if (name == "F") {
        if (state_.frozen_pose) state_.frozen_pose.reset();
        else state_.frozen_pose = state_.pose;
        return change_frame;
    }
    if (name == "H") state_.ui_visible = !state_.ui_visible;
    if (name == "R") {
        state_.pose = initial_pose_;
        return change_frame;
    }
    if (name == "SPACE") state_.playing = !state_.playing;
    if (name == "F12") screenshot_due_ = next_screenshot_name();
    if (name == "ESCAPE") quit_ = true;
    return change_none;
}

unsigned ViewerApp::track_movement() {
    const bool was_moving = view_moving_;
    view_moving_ = mouse_dragging_ || state_.script_drag || Clock::now() - last_wheel_ < wheel_moves_for;
    return view_moving_ != was_moving && state_.interaction_fps > 0 ? change_frame : change_none;
}

unsigned ViewerApp::mouse_camera() {
    const ImGuiIO& io = ImGui::GetIO();
    mouse_dragging_ = false;
    if (io.WantCaptureMouse || window_fb_height_ <= 0) return change_none;
    mouse_dragging_ = ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0) || ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0) ||
                      ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0);
    const float height = float(window_fb_height_);
    const pipeline::Camera camera = camera_for(state_.pose);
    unsigned changes = change_none;
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0) && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        orbit(state_.pose, -drag_degrees(io.MouseDelta.x, window_fb_height_), drag_degrees(io.MouseDelta.y, window_fb_height_));
        changes = change_frame;
    }
    const bool panning = ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0) || ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0);
    if (panning && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        pan(state_.pose, camera, io.MouseDelta.x / height, -io.MouseDelta.y / height);
        changes = change_frame;
    }
    if (io.MouseWheel != 0) {
        last_wheel_ = Clock::now();
        zoom(state_.pose, camera, std::pow(0.9f, io.MouseWheel));
        changes = change_frame;
    }
    return changes;
}

bool ViewerApp::run_step(const ScriptStep& step, unsigned& changes) {
    std::cout << "cutaway view: " << describe(script_->script(), step) << '\n' << std::flush;
    const auto number = [&](std::size_t i) { return std::stof(step.args.at(i)); };
    const pipeline::Camera camera = camera_for(state_.pose);
    if (step.action == "orbit") orbit(state_.pose, number(0), number(1));
    else if (step.action == "pan") pan(state_.pose, camera, number(0), number(1));
    else if (step.action == "zoom") zoom(state_.pose, camera, number(0));
    else if (step.action == "camera") state_.pose = {number(0), number(1), number(2), glm::vec3(0)};
    else if (step.action == "set") changes |= apply_option_tokens(state_.options, step.args);
    else if (step.action == "key") changes |= press_key(step.args.at(0));
    else if (step.action == "drag") state_.script_drag = on_off(step.args.at(0));
    else if (step.action == "freeze") {
        if (on_off(step.args.at(0)) != state_.frozen_pose.has_value()) changes |= press_key("F");
    } else if (step.action == "play") state_.playing = on_off(step.args.at(0));
    else if (step.action == "playback") {
        state_.coherence = step.args.at(0);
        state_.frames_per_step = std::stoi(step.args.at(1));
    }
    else if (step.action == "ui") state_.ui_visible = on_off(step.args.at(0));
    else if (step.action == "volumes") changes |= volume_command(step.args);
    else if (step.action == "screenshot") {
        screenshot_due_ = step.args.at(0);
        changes |= change_frame;
        return true;
    } else if (step.action == "quit") {
        quit_ = true;
        return true;
    } else {
        throw std::invalid_argument("action '" + step.action + "' is not handled by the viewer");
    }
    changes |= change_frame;
    return false;
}

unsigned ViewerApp::advance_play() {
    if (!state_.playing || scene_->step_count() == 0) {
        if (!player_) return change_none;
        player_.reset();  // paused: the frame stays as played
        return change_frame;
    }
    const temporal::Coherence coherence = temporal::parse_coherence(state_.coherence);
    const std::size_t frames_per_step = std::size_t(std::max(1, state_.frames_per_step));
    if (!player_ || player_->settings().coherence != coherence || player_->settings().frames_per_step != frames_per_step)
        player_ = scene_->player(coherence, frames_per_step, std::size_t(std::max(state_.options.step, 0)));
    const temporal::CoherentSequence::Frame frame = player_->next();
    scene_->show(frame);
    played_time_step_ = frame.time_step;
    state_.options.step = int(frame.time_step);  // the step slider follows the played frames
    return change_frame;
}

double ViewerApp::shown_time_step() const { return player_ ? played_time_step_ : double(std::max(state_.options.step, 0)); }

void ViewerApp::apply(unsigned changes) {
    if (changes == change_none) return;
    // A new step, property or range starts playing afresh from the options' step.
    if (changes & change_selection) player_.reset();
    settings_ = state_.options.frame_settings();
    if (changes & change_selection) {
        try {
            scene_->select(state_.options);
            info_.message.clear();
        } catch (const std::invalid_argument& error) {
            if (script_) throw;
            info_.message = error.what();  // the panel shows it; the previous selection stays
        }
    }
    if (changes & change_cut_volumes) {
        try {
            scene_->set_cut_volumes(state_.cut_volumes);
        } catch (const std::invalid_argument& error) {
            if (script_) throw;
            info_.message = error.what();  // the panel shows it; the volumes drawn stay
            state_.cut_volumes = scene_->cut_volumes();
        }
    }
    needs_render_ = true;  // a new size (change_size) is taken before the frame is drawn
}

void ViewerApp::reload_shaders_if_edited() {
    // A few scans a second notice an editor's save at once without statting every file each frame.
    const Clock::time_point now = Clock::now();
    if (now - last_shader_scan_ < std::chrono::milliseconds(250)) return;
    last_shader_scan_ = now;
    if (!shader_watcher_.poll()) return;
    try {
        scene_->rebuild_renderer(render_width(), render_height(), settings_);
        info_.message = "shaders reloaded";
        std::cout << "cutaway view: shaders reloaded from " << shaders_.root().string() << '\n' << std::flush;
    } catch (const gl::GlError& error) {
        info_.message = std::string("shader edit not applied: ") + error.what();
        std::cerr << "cutaway view: " << info_.message << '\n';
    }
    needs_render_ = true;
}

void ViewerApp::sync_freeze() {
    pipeline::CutawayRenderer& renderer = scene_->renderer();
    if (state_.frozen_pose && !renderer.status().frozen) renderer.freeze(camera_for(*state_.frozen_pose));
    if (!state_.frozen_pose && renderer.status().frozen) renderer.freeze(std::nullopt);
}

void ViewerApp::write_screenshot(const std::string& path) const {
    gl::write_png(gl::read_rgba(0, 0, window_fb_width_, window_fb_height_), path);
    std::cout << "cutaway view: screenshot " << path << '\n' << std::flush;
}

std::string ViewerApp::next_screenshot_name() {
    char name[64];
    std::snprintf(name, sizeof name, "cutaway-view-%03d.png", ++screenshots_taken_);
    return name;
}

void ViewerApp::write_stats() const {
    nlohmann::json stats = timings_.to_json();
    stats["configuration"] = state_.options.describe();
    stats["camera_final"] = {state_.pose.azimuth_deg, state_.pose.elevation_deg, state_.pose.distance};
    stats["window_size"] = {window_fb_width_, window_fb_height_};
    stats["render_size"] = {render_width(), render_height()};
    stats["render_scale"] = state_.render_scale;
    stats["interaction_fps"] = state_.interaction_fps;
    stats["model"] = scene_->description();
    stats["primary_cells"] = scene_->primary_count();
    stats["script"] = options_.script;
    stats.update(app::run_context_json(app::current_gl_device(window_.platform())));
    stats["timing"] = "loop_ms: wall clock of one viewer loop pass (events, script, panel, render when something "
                      "changed, blit, swap); stages_ms: fenced wall-clock stage times of the cutaway frame";
    io::write_file(options_.stats, stats.dump(2) + '\n');
}

}  // namespace cutaway::viewer
