#include "viewer/step_overlay.h"
#include "viewer/imgui_session.h"

#include <imgui.h>

namespace cutaway::viewer {

void draw_step_overlay(const std::string& caption, float colour_bar_share) {
    if (caption.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    // Top right, beside the columns the colour bar keeps (the panel holds the top left).
    const float right = viewport->WorkPos.x + viewport->WorkSize.x * (1.0f - colour_bar_share) - ui_px(8);
    ImGui::SetNextWindowPos(ImVec2(right, viewport->WorkPos.y + ui_px(8)), ImGuiCond_Always, ImVec2(1, 0));
    // Sized from this frame's text: auto-resizing follows a frame late and clips a caption that grew.
    const ImVec2 padding = ImGui::GetStyle().WindowPadding;
    const ImVec2 text = ImGui::CalcTextSize(caption.c_str());
    ImGui::SetNextWindowSize(ImVec2(text.x + 2 * padding.x, text.y + 2 * padding.y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
    if (ImGui::Begin("step", nullptr, flags)) ImGui::TextUnformatted(caption.c_str());
    ImGui::End();
}

}  // namespace cutaway::viewer
