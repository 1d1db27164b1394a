#pragma once
// One small interface over the graphics backend, chosen by name: "egl" (headless) here, "glfw"
// (a window) for the viewer. Nothing outside src/gl/ knows which one runs.
#include <memory>
#include <string>

namespace cutaway::gl {

struct ContextOptions {
    std::string backend = "egl";         ///< "egl" (headless) or "glfw" (window, viewer only)
    std::string egl_platform = "auto";   ///< "auto", "surfaceless" (Mesa) or "device" (NVIDIA)
    bool debug_output = false;           ///< KHR_debug messages to stderr (on in debug builds)
    int window_width = 1280;             ///< glfw only
    int window_height = 720;             ///< glfw only
    std::string window_title = "cutaway";
};

/// A current OpenGL 4.5 core context. Destroying it releases the context (and the window).
class GlContext {
public:
    virtual ~GlContext() = default;
    /// Platform actually used, e.g. "egl/surfaceless" or "egl/device".
    virtual std::string platform() const = 0;
    /// Presents the default framebuffer (windowed backends); a no-op headless.
    virtual void swap_buffers() {}
};

/// Creates a context for `options.backend` and makes it current; throws GlError with the reason
/// (no EGL display, no GL 4.5 core, no display for a window) when none can be made.
std::unique_ptr<GlContext> create_context(const ContextOptions& options);

/// GL_RENDERER, GL_VERSION of the current context.
std::string gl_renderer();
std::string gl_version();

}  // namespace cutaway::gl
