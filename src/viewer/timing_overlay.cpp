#include "viewer/timing_overlay.h"

#include <imgui.h>

namespace cutaway::viewer {

void draw_timing_overlay(const FrameTimings& timings, float colour_bar_share) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    // Bottom right, beside the columns the colour bar keeps (its lowest labels reach down to the
    // bottom third of the window, where the overlay's table is).
    const float right = viewport->WorkPos.x + viewport->WorkSize.x * (1.0f - colour_bar_share) - 8;
    ImGui::SetNextWindowPos(ImVec2(right, viewport->WorkPos.y + viewport->WorkSize.y - 8), ImGuiCond_Always, ImVec2(1, 1));
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("timing", nullptr, flags)) {
        // Medians of the loops that drew a frame and of those that did not (nothing changed): the
        // last loop alone, often an idle one, gave a rate the viewer never reached while drawing.
        const double frame_ms = timings.loop_ms_rendering();
        ImGui::Text("frame (median of those drawn): %.1f ms, %.1f fps", frame_ms, frame_ms > 0 ? 1000.0 / frame_ms : 0.0);
        ImGui::Text("loop without drawing (median): %.1f ms", timings.loop_ms_idle());
        ImGui::Separator();
        ImGui::Text("stage medians of the last %zu frames (fenced)", timings.window());
        if (ImGui::BeginTable("stages", 3, ImGuiTableFlags_SizingFixedFit)) {
            ImGui::TableSetupColumn("stage");
            ImGui::TableSetupColumn("wall ms");
            ImGui::TableSetupColumn("GL query ms");
            ImGui::TableHeadersRow();
            for (const std::string& name : timings.stage_order()) {
                const StageMedian stage = timings.stage(name);
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(name.c_str());
                ImGui::TableNextColumn();
                ImGui::Text("%8.2f", stage.wall_ms);
                ImGui::TableNextColumn();
                if (stage.gl_query_valid) ImGui::Text("%8.2f", stage.gl_query_ms);
                else ImGui::TextDisabled("%8.2f invalid", stage.gl_query_ms);
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
}

}  // namespace cutaway::viewer
