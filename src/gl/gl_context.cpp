#include "gl/gl_context.h"

#include <epoxy/gl.h>

#include "gl/egl_context.h"
#include "gl/gl_error.h"

namespace cutaway::gl {

std::unique_ptr<GlContext> create_context(const ContextOptions& options) {
    // One line per backend.
    if (options.backend == "egl") return create_egl_context(options);
    throw GlError("graphics backend '" + options.backend + "': expected egl");
}

std::string gl_renderer() {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return text ? text : "unknown";
}

std::string gl_version() {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return text ? text : "unknown";
}

}  // namespace cutaway::gl
