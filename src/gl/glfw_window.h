#pragma once
// A desktop window with an OpenGL 4.5 core context (GLFW), for the interactive viewer. It is a
// GlContext like the headless EGL one, so everything that renders offscreen renders here too.
#include <memory>
#include <string>

#include "gl/gl_context.h"

struct GLFWwindow;

namespace cutaway::gl {

struct WindowOptions {
    int width = 1280;
    int height = 720;
    std::string title = "cutaway";
    bool debug_output = false;  ///< KHR_debug messages to stderr
};

class GlfwWindow final : public GlContext {
public:
    /// Opens the window and makes its context current. Throws GlError naming the reason (no
    /// display, no OpenGL 4.5 core context) when it cannot.
    explicit GlfwWindow(const WindowOptions& options);
    ~GlfwWindow() override;
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    /// "glfw/x11" or "glfw/wayland".
    std::string platform() const override { return platform_; }
    GLFWwindow* handle() const { return window_; }

    bool close_requested() const;
    void request_close();
    /// Framebuffer size in pixels (may differ from the window size on high-DPI screens).
    int framebuffer_width() const;
    int framebuffer_height() const;
    void swap_buffers();

private:
    GLFWwindow* window_ = nullptr;
    bool initialised_ = false;
    std::string platform_;
};

}  // namespace cutaway::gl
