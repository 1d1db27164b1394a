#pragma once
// Headless EGL backend of GlContext.
#include "gl/gl_context.h"

namespace cutaway::gl {

std::unique_ptr<GlContext> create_egl_context(const ContextOptions& options);

}  // namespace cutaway::gl
