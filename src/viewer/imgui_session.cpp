#include "viewer/imgui_session.h"

#include <epoxy/gl.h>
// epoxy first: the backends must not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "gl/gl_error.h"

namespace cutaway::viewer {

namespace {
constexpr float default_font_px = 13.0f;  // Dear ImGui's ProggyClean
}  // namespace

ImGuiSession::ImGuiSession(gl::GlfwWindow& window, float ui_scale) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini written into the working directory
    ImFontConfig font;
    font.SizePixels = default_font_px * ui_scale;
    io.Fonts->AddFontDefault(&font);
    ImGui::StyleColorsDark();
    ImGui::GetStyle().ScaleAllSizes(ui_scale);
    if (!ImGui_ImplGlfw_InitForOpenGL(window.handle(), true) || !ImGui_ImplOpenGL3_Init("#version 450")) {
        ImGui::DestroyContext();
        throw gl::GlError("Dear ImGui could not start on the window's OpenGL context");
    }
}

ImGuiSession::~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

float ui_px(float px) { return px * ImGui::GetFontSize() / default_font_px; }

void ImGuiSession::begin_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiSession::end_frame(bool draw) {
    ImGui::Render();
    if (draw) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace cutaway::viewer
