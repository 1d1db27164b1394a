#include "gl/glfw_window.h"

#include <epoxy/gl.h>
// epoxy first: GLFW must not pull in the system GL header.
#include <GLFW/glfw3.h>

#include "gl/debug_output.h"
#include "gl/gl_error.h"

namespace cutaway::gl {
namespace {

/// The description of GLFW's last error (GLFW keeps it per thread; no callback needed).
std::string last_glfw_error() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR) return "no reason given";
    return description ? description : "GLFW error " + std::to_string(code);
}

std::string platform_name() {
#if GLFW_VERSION_MAJOR > 3 || (GLFW_VERSION_MAJOR == 3 && GLFW_VERSION_MINOR >= 4)
    return glfwGetPlatform() == GLFW_PLATFORM_WAYLAND ? "glfw/wayland" : "glfw/x11";
#else
    return "glfw/x11";
#endif
}

}  // namespace

GlfwWindow::GlfwWindow(const WindowOptions& options) {
    if (options.width < 1 || options.height < 1)
        throw GlError("window size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                      ": expected positive sides");
    if (!glfwInit())
        throw GlError("no display for a window (" + last_glfw_error() +
                      "); run on a desktop session or under xvfb-run, or use `cutaway render` for headless frames");
    initialised_ = true;
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug_output ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        const std::string reason = last_glfw_error();
        glfwTerminate();
        throw GlError("cannot open a window with an OpenGL 4.5 core context (" + reason + ")");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0);  // frame times measure rendering, not the display's refresh
    platform_ = platform_name();
    if (epoxy_gl_version() < 45) {
        const int version = epoxy_gl_version();
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw GlError("window context reports OpenGL " + std::to_string(version) + ", need 45");
    }
    if (options.debug_output) enable_debug_output();
}

GlfwWindow::~GlfwWindow() {
    if (window_ != nullptr) glfwDestroyWindow(window_);
    if (initialised_) glfwTerminate();
}

bool GlfwWindow::close_requested() const { return glfwWindowShouldClose(window_) != 0; }
void GlfwWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

int GlfwWindow::framebuffer_width() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return width;
}

int GlfwWindow::framebuffer_height() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return height;
}

void GlfwWindow::swap_buffers() { glfwSwapBuffers(window_); }

}  // namespace cutaway::gl
