#pragma once
// Dear ImGui bound to a GLFW window and its OpenGL 4.5 context, for the lifetime of this object.
#include "gl/glfw_window.h"

namespace cutaway::viewer {

class ImGuiSession {
public:
    /// Call after the window's own input callbacks are installed: ImGui chains to them.
    /// `ui_scale`: the text and widgets at this multiple of Dear ImGui's 13 px default font (the
    /// font rasterised at that size, not magnified), e.g. 2 for a screenshot that prints.
    ImGuiSession(gl::GlfwWindow& window, float ui_scale);
    ~ImGuiSession();
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;

    void begin_frame();
    /// Draws the frame's widgets onto the bound framebuffer (or only ends the frame when `draw` is false).
    void end_frame(bool draw);
};

/// `px` pixels of the default 13 px font's layout at the session's scale (widget sizes the
/// panels set themselves; Dear ImGui scales its own style).
float ui_px(float px);

}  // namespace cutaway::viewer
