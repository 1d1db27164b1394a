#pragma once
// A KHR_debug group around a scope: a RenderDoc or Nsight capture of a frame shows each stage and
// pass by the name stats.json gives it.
#include <epoxy/gl.h>

namespace cutaway::gl {

class DebugGroup {
public:
    explicit DebugGroup(const char* name) { glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name); }
    ~DebugGroup() { glPopDebugGroup(); }
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace cutaway::gl
