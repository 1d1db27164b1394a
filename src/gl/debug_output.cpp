#include "gl/debug_output.h"

#include <epoxy/gl.h>

#include <iostream>

namespace cutaway::gl {
namespace {

void GLAPIENTRY print_message(GLenum /*source*/, GLenum type, GLuint id, GLenum severity, GLsizei /*length*/,
                              const GLchar* message, const void* /*user*/) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    const char* kind = type == GL_DEBUG_TYPE_ERROR ? "error" : type == GL_DEBUG_TYPE_PERFORMANCE ? "performance" : "message";
    std::cerr << "GL " << kind << " " << id << ": " << message << '\n';
}

}  // namespace

void enable_debug_output() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(print_message, nullptr);
}

}  // namespace cutaway::gl
