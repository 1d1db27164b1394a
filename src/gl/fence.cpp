#include "gl/fence.h"

#include "gl/gl_error.h"

namespace cutaway::gl {

void Fence::wait() const {
    constexpr GLuint64 second_ns = 1000000000;
    for (;;) {
        switch (glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, second_ns)) {
            case GL_ALREADY_SIGNALED:
            case GL_CONDITION_SATISFIED: return;
            case GL_TIMEOUT_EXPIRED: continue;  // a long draw: keep waiting
            default: throw GlError("glClientWaitSync failed waiting for a fence");
        }
    }
}

}  // namespace cutaway::gl
