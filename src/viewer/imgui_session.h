#pragma once
// Dear ImGui bound to a GLFW window and its OpenGL 4.5 context, for the lifetime of this object.
#include "gl/glfw_window.h"

namespace cutaway::viewer {

class ImGuiSession {
public:
    /// Call after the window's own input callbacks are installed: ImGui chains to them.
    explicit ImGuiSession(gl::GlfwWindow& window);
    ~ImGuiSession();
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;

    void begin_frame();
    /// Draws the frame's widgets onto the bound framebuffer (or only ends the frame when `draw` is false).
    void end_frame(bool draw);
};

}  // namespace cutaway::viewer
