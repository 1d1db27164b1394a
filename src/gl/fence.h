#pragma once
// A GL sync object (glFenceSync) owned like every other GL object: deleted with it.
#include <epoxy/gl.h>

#include <utility>

namespace cutaway::gl {

class Fence {
public:
    /// Signalled once every command issued before it has completed.
    Fence() : sync_(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0)) {}
    ~Fence() {
        if (sync_) glDeleteSync(sync_);
    }
    Fence(Fence&& other) noexcept : sync_(std::exchange(other.sync_, nullptr)) {}
    Fence& operator=(Fence&& other) noexcept {
        std::swap(sync_, other.sync_);
        return *this;
    }
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;

    /// Flushes and blocks until the fence is signalled; throws GlError if the wait fails.
    void wait() const;

private:
    GLsync sync_ = nullptr;
};

}  // namespace cutaway::gl
