#include "viewer/timing_overlay.h"
#include "viewer/imgui_session.h"

#include <imgui.h>

namespace cutaway::viewer {

ImVec2 draw_timing_overlay(const FrameTimings& timings) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + ui_px(8), viewport->WorkPos.y + viewport->WorkSize.y - ui_px(8)),
                            ImGuiCond_Always, ImVec2(0, 1));
    ImGui::SetNextWindowBgAlpha(0.6f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
    if (ImGui::Begin("timing", nullptr, flags)) {
        // Medians of the loops that drew a frame and of those that did not (nothing changed): the
        // last loop alone, often an idle one, gave a rate the viewer never reached while drawing.
        // Short lines: the overlay is no wider than the panel above it.
        const double frame_ms = timings.loop_ms_rendering();
        ImGui::Text("frame %.1f ms, %.1f fps", frame_ms, frame_ms > 0 ? 1000.0 / frame_ms : 0.0);
        ImGui::TextUnformatted("(median of the frames drawn)");
        ImGui::Text("loop without drawing %.1f ms", timings.loop_ms_idle());
        ImGui::Separator();
        ImGui::Text("stages: medians of %zu frames", timings.window());
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
    const ImVec2 size = ImGui::GetWindowSize();
    ImGui::End();
    return size;
}

}  // namespace cutaway::viewer
