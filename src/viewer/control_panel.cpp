#include "viewer/control_panel.h"
#include "viewer/imgui_session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <variant>
#include <imgui.h>

#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/setting_names.h"
#include "cutaway/temporal/coherence.h"
#include "volumes/cut_volume.h"
#include "wells/well_selection.h"

namespace cutaway::viewer {
namespace {

/// A combo over `choices` editing a string option; true when it changed.
bool choice_combo(const char* label, std::string& value, const std::vector<std::string>& choices) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const std::string& choice : choices) {
            const bool selected = choice == value;
            if (ImGui::Selectable(choice.c_str(), selected) && !selected) {
                value = choice;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

/// A checkbox over an "on"/"off" option.
bool on_off_checkbox(const char* label, std::string& value) {
    const pipeline::ChoiceTable<bool> words = pipeline::on_off_choices();
    bool on = pipeline::find_choice(words, value).value_or(false);
    if (!ImGui::Checkbox(label, &on)) return false;
    value = pipeline::name_of_choice(words, on);
    return true;
}

std::vector<std::string> property_names(const grid::CornerPointGrid& grid) {
    std::vector<std::string> names = grid.property_names();
    for (const std::string& name : grid.dynamic_property_names()) names.push_back(name);
    return names;
}

/// Play/pause, the frames drawn from one report step to the next and how they move between
/// steps (none: each step held; smooth: interpolated, as `cutaway animate --coherence`). The
/// player reads them each frame, so they need no Change bit.
void play_controls(ViewerState& state) {
    if (ImGui::Button(state.playing ? "pause [SPACE]" : "play [SPACE]")) state.playing = !state.playing;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ui_px(120));
    choice_combo("coherence", state.coherence, temporal::coherence_names());
    ImGui::SliderInt("frames/step", &state.frames_per_step, 1, 60);
}

unsigned property_section(ViewerState& state, const ViewerScene& scene) {
    app::RenderOptions& o = state.options;
    const app::PropertyChoice& property = scene.property();
    unsigned changes = change_none;
    std::string name = property.name;
    const std::vector<std::string> names = property_names(scene.grid());
    if (!names.empty() && choice_combo("property", name, names)) {
        o.property = name;
        o.step = scene.grid().step_count(name) > 0 ? 0 : -1;
        o.range.clear();
        o.primary_fraction = 0;
        changes |= change_selection;
    }
    ImGui::Text("%zu primary cells of %zu active", scene.primary_count(), scene.grid().active_count());
    // The histogram's caption on its own line: written over the bars it could not be read.
    const PropertyHistogram& histogram = scene.histogram();
    ImGui::TextDisabled("active cells per %s value", name.c_str());
    ImGui::PlotHistogram("##histogram", histogram.counts.data(), int(histogram.counts.size()), 0, nullptr, 0.0f,
                         FLT_MAX, ImVec2(0, ui_px(60)));
    float low = property.primary_range.min, high = property.primary_range.max;
    const float lo_limit = property.colour_range.min, hi_limit = property.colour_range.max;
    bool range_changed = ImGui::SliderFloat("primary min", &low, lo_limit, hi_limit, "%.4g");
    range_changed |= ImGui::SliderFloat("primary max", &high, lo_limit, hi_limit, "%.4g");
    if (range_changed) {
        o.range = {std::min(low, high), std::max(low, high)};
        o.primary_fraction = 0;
        changes |= change_selection;
    }
    if (const std::size_t steps = scene.step_count(); steps > 0) {
        int step = std::max(o.step, 0);
        if (ImGui::SliderInt("time step", &step, 0, int(steps) - 1)) {
            o.step = step;
            changes |= change_selection;
        }
        play_controls(state);
    }
    return changes;
}

unsigned cut_section(ViewerState& state) {
    app::RenderOptions& o = state.options;
    bool changed = choice_combo("strategy", o.settings.strategy, pipeline::cut_strategy_names());
    changed |= choice_combo("seeds", o.seeds, pipeline::choice_names<pipeline::SeedSource>());
    changed |= ImGui::SliderFloat("aperture H (full)", &o.aperture[0], 0, 180, "%.1f deg");
    changed |= ImGui::SliderFloat("aperture V (full)", &o.aperture[1], 0, 180, "%.1f deg");
    changed |= ImGui::Checkbox("aperture 180 (remove all in front)", &o.aperture_180);
    bool frozen = state.frozen_pose.has_value();
    if (ImGui::Checkbox("freeze view [F]", &frozen)) {
        if (frozen) state.frozen_pose = state.pose;
        else state.frozen_pose.reset();
        changed = true;
    }
    return changed ? change_frame : change_none;
}

unsigned lines_and_post_section(ViewerState& state) {
    app::RenderOptions& o = state.options;
    pipeline::FrameSettings& s = o.settings;
    bool changed = choice_combo("border", o.border, pipeline::choice_names<pipeline::BorderMode>());
    changed |= ImGui::SliderFloat("border width", &s.border_width_px, 1, 8, "%.1f px");
    changed |= ImGui::SliderFloat("line width", &s.line_width_px, 0, 4, "%.1f px");
    changed |= ImGui::Checkbox("hide internal lines", &s.hide_internal_lines);
    changed |= on_off_checkbox("shell contours", o.contours);
    changed |= ImGui::Checkbox("silhouette", &s.silhouette);
    int half = s.mean_filter > 1 ? (s.mean_filter - 1) / 2 : 0;
    char format[32];
    std::snprintf(format, sizeof format, half ? "k = %d" : "off", 2 * half + 1);
    if (ImGui::SliderInt("mean filter", &half, 0, 16, format)) {
        s.mean_filter = half ? 2 * half + 1 : 0;
        changed = true;
    }
    changed |= choice_combo("kernel", o.kernel, pipeline::choice_names<pipeline::MeanFilterKernel>());
    changed |= on_off_checkbox("SSAO", o.ssao);
    changed |= choice_combo("SSAO resolution", o.ssao_resolution, pipeline::choice_names(pipeline::ssao_resolution_choices()));
    changed |= ImGui::Checkbox("saturation contrast", &s.saturation);
    changed |= choice_combo("show", o.only, pipeline::choice_names<pipeline::OnlyLayer>());
    changed |= ImGui::Checkbox("colour bar", &s.colour_bar);
    return changed ? change_frame : change_none;
}

unsigned view_section(ViewerState& state, const PanelInfo& info, PanelRequests& requests) {
    unsigned changes = change_none;
    const char* scales[] = {"100%", "75%", "50%", "25%"};
    const float values[] = {1.0f, 0.75f, 0.5f, 0.25f};
    int current = int(std::find(std::begin(values), std::end(values), state.render_scale) - std::begin(values));
    if (ImGui::Combo("render scale", &current, scales, IM_ARRAYSIZE(scales)) && current < IM_ARRAYSIZE(values)) {
        state.render_scale = values[current];
        changes |= change_size;
    }
    // While a drag turns the view, frames are drawn smaller to hold this rate (0: never smaller).
    ImGui::SliderFloat("fps while moving", &state.interaction_fps, 0.0f, 30.0f, state.interaction_fps > 0 ? "%.0f" : "off");
    ImGui::Text("render %d x %d", info.render_width, info.render_height);
    if (state.pose.distance > 0)
        ImGui::Text("camera az %.1f el %.1f dist %.4g", state.pose.azimuth_deg, state.pose.elevation_deg, state.pose.distance);
    else
        ImGui::Text("camera az %.1f el %.1f (framed)", state.pose.azimuth_deg, state.pose.elevation_deg);
    if (ImGui::Button("reset camera [R]")) requests.reset_camera = true;
    ImGui::SameLine();
    if (ImGui::Button("screenshot [F12]")) requests.screenshot = true;
    ImGui::TextDisabled("drag: orbit, right drag: pan, wheel: zoom, H: hide panel");
    return changes;
}

/// Edits one volume's numbers (drag: `speed` model units per pixel); true when one changed. A mesh
/// is shown by its file only.
bool edit_volume(volumes::CutVolume& volume, double speed) {
    const auto drag3 = [speed](const char* label, grid::Point3& p) {
        return ImGui::DragScalarN(label, ImGuiDataType_Double, &p.x, 3, float(speed), nullptr, nullptr, "%.1f");
    };
    const double least = 0.0;
    struct Editor {
        decltype(drag3)& drag;
        double speed;
        const double& least;
        bool operator()(volumes::BoxVolume& b) const { return drag("min", b.min) | drag("max", b.max); }
        bool operator()(volumes::CylinderVolume& c) const {
            return drag("from", c.from) | drag("to", c.to) |
                   ImGui::DragScalar("radius", ImGuiDataType_Double, &c.radius, float(speed), &least, nullptr, "%.1f");
        }
        bool operator()(volumes::WellVolume& w) const {
            ImGui::Text("well %s", w.name.c_str());
            double radius = w.radius.value_or(0);
            if (!ImGui::DragScalar("radius (0: default)", ImGuiDataType_Double, &radius, float(speed), &least, nullptr, "%.1f"))
                return false;
            w.radius = radius > 0 ? std::optional<double>(radius) : std::nullopt;
            return true;
        }
        bool operator()(volumes::MeshVolume& m) const {
            ImGui::Text("mesh %s", m.file.c_str());
            return false;
        }
    };
    return std::visit(Editor{drag3, speed, least}, volume);
}

/// --wells with its selection set to all (`shown`) or none, its FILE kept.
std::vector<std::string> wells_toggled(const std::vector<std::string>& values, bool shown) {
    std::vector<std::string> toggled;
    for (const std::string& value : values)
        if (wells::names_a_file(value)) toggled.push_back(value);
    toggled.push_back(shown ? "all" : "none");
    return toggled;
}

/// The cut volumes: each one's numbers and a remove button; a box, a cylinder or a cut around a
/// well added at the model's centre; the list saved to or loaded from a JSON file (the
/// --cut-volumes format, so `render --cut-volumes FILE` draws the same cut headless).
unsigned volumes_section(ViewerState& state, const ViewerScene& scene, PanelRequests& requests) {
    const grid::Box3& b = scene.bounds();
    const grid::Point3 centre{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y), 0.5 * (b.min.z + b.max.z)};
    const grid::Point3 quarter{0.25 * (b.max.x - b.min.x), 0.25 * (b.max.y - b.min.y), 0.25 * (b.max.z - b.min.z)};
    const double speed = std::max(quarter.x, quarter.y) / 50;
    unsigned changes = change_none;
    if (!scene.well_names().empty()) {
        bool shown = wells::parse_wells_option(state.options.wells).draws();
        if (ImGui::Checkbox("draw wells", &shown)) {
            state.options.wells = wells_toggled(state.options.wells, shown);
            changes |= change_selection;
        }
    }
    for (std::size_t i = 0; i < state.cut_volumes.size(); ++i) {
        ImGui::PushID(int(i));
        ImGui::Text("%zu: %s", i + 1, volumes::kind_name(state.cut_volumes[i]));
        ImGui::SameLine();
        const bool removed = ImGui::SmallButton("remove");
        if (!removed && edit_volume(state.cut_volumes[i], speed)) changes |= change_cut_volumes;
        ImGui::PopID();
        if (removed) {
            state.cut_volumes.erase(state.cut_volumes.begin() + std::ptrdiff_t(i));
            return changes | change_cut_volumes;
        }
    }
    if (ImGui::Button("add box")) {
        state.cut_volumes.push_back(volumes::BoxVolume{{centre.x - quarter.x, centre.y - quarter.y, b.min.z},
                                                       {centre.x + quarter.x, centre.y + quarter.y, centre.z}});
        changes |= change_cut_volumes;
    }
    ImGui::SameLine();
    if (ImGui::Button("add cylinder")) {
        state.cut_volumes.push_back(volumes::CylinderVolume{{centre.x, centre.y, b.min.z}, {centre.x, centre.y, b.max.z},
                                                            0.5 * std::min(quarter.x, quarter.y)});
        changes |= change_cut_volumes;
    }
    for (const std::string& name : scene.well_names()) {
        ImGui::SameLine();
        if (ImGui::SmallButton(("cut " + name).c_str())) {
            state.cut_volumes.push_back(volumes::WellVolume{name, std::nullopt});
            changes |= change_cut_volumes;
        }
    }
    char file[512];
    std::snprintf(file, sizeof file, "%s", state.cut_volumes_file.c_str());
    if (ImGui::InputText("file", file, sizeof file)) state.cut_volumes_file = file;
    if (ImGui::Button("save")) requests.volumes = {"save", state.cut_volumes_file};
    ImGui::SameLine();
    if (ImGui::Button("load")) requests.volumes = {"load", state.cut_volumes_file};
    return changes;
}

}  // namespace

unsigned draw_control_panel(ViewerState& state, const ViewerScene& scene, const PanelInfo& info,
                            PanelRequests& requests) {
    ImGui::SetNextWindowPos(ImVec2(ui_px(8), ui_px(8)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(ui_px(420), 0), ImGuiCond_FirstUseEver);  // 360 clipped "aperture H (full)"
    // Above the timing overlay (timing_overlay.h): at most the height it leaves, scrolled beyond.
    const float free_height = ImGui::GetMainViewport()->WorkSize.y - state.overlay_height - ui_px(24);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(FLT_MAX, std::max(free_height, ui_px(100))));
    unsigned changes = change_none;
    if (ImGui::Begin("cutaway")) {
        ImGui::TextWrapped("%s", scene.description().c_str());
        ImGui::TextDisabled("%s", info.gl_renderer.c_str());
        if (!info.message.empty()) ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "%s", info.message.c_str());
        if (!info.step_caption.empty()) ImGui::TextUnformatted(info.step_caption.c_str());
        if (ImGui::CollapsingHeader("property and primaries", ImGuiTreeNodeFlags_DefaultOpen))
            changes |= property_section(state, scene);
        if (ImGui::CollapsingHeader("cut", ImGuiTreeNodeFlags_DefaultOpen)) changes |= cut_section(state);
        if (ImGui::CollapsingHeader("cut volumes and wells")) changes |= volumes_section(state, scene, requests);
        if (ImGui::CollapsingHeader("lines and post-processing")) changes |= lines_and_post_section(state);
        if (ImGui::CollapsingHeader("view", ImGuiTreeNodeFlags_DefaultOpen)) changes |= view_section(state, info, requests);
    }
    const float width = ImGui::GetIO().DisplaySize.x;
    const float right = std::max(ImGui::IsWindowCollapsed() ? 0.0f : ImGui::GetWindowPos().x + ImGui::GetWindowWidth(),
                                 state.overlay_width > 0 ? ui_px(8) + state.overlay_width : 0.0f);
    const float share = width <= 0 ? 0.0f : right / width;
    if (std::abs(share - state.panel_share) > 1e-3f) changes |= change_frame;
    state.panel_share = share;
    ImGui::End();
    return changes;
}

}  // namespace cutaway::viewer
