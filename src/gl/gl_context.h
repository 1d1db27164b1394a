#pragma once
// One small interface over the graphics backend, chosen by name (create_context). Only "egl"
// (headless) exists yet; a windowed backend for the viewer plugs in beside it. Nothing outside
// src/gl/ knows which one runs.
#include <memory>
#include <string>

namespace cutaway::gl {

struct ContextOptions {
    std::string backend = "egl";         ///< "egl" (headless)
    std::string egl_platform = "auto";   ///< "auto", "surfaceless" (Mesa) or "device" (NVIDIA)
    bool debug_output = false;           ///< KHR_debug messages to stderr (on in debug builds)
};

/// A current OpenGL 4.5 core context. Destroying it releases the context.
class GlContext {
public:
    virtual ~GlContext() = default;
    /// Platform actually used, e.g. "egl/surfaceless" or "egl/device".
    virtual std::string platform() const = 0;
};

/// Creates a context for `options.backend` and makes it current; throws GlError with the reason
/// (no EGL display, no GL 4.5 core) when none can be made.
std::unique_ptr<GlContext> create_context(const ContextOptions& options);

/// GL_RENDERER, GL_VERSION of the current context.
std::string gl_renderer();
std::string gl_version();

}  // namespace cutaway::gl
