#pragma once
// The rasteriser's triangle culling, on for one scope (glFrontFace back to GL_CCW at its end).
#include <epoxy/gl.h>

namespace cutaway::gl {

class FaceCulling {
public:
    /// `culled`: GL_FRONT or GL_BACK; the winding of front-facing triangles is glFrontFace's.
    explicit FaceCulling(GLenum culled) {
        glCullFace(culled);
        glEnable(GL_CULL_FACE);
    }
    ~FaceCulling() {
        glDisable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
    }
    FaceCulling(const FaceCulling&) = delete;
    FaceCulling& operator=(const FaceCulling&) = delete;
};

}  // namespace cutaway::gl
