#pragma once
// The rasteriser's triangle culling, on for one scope.
#include <epoxy/gl.h>

namespace cutaway::gl {

class FaceCulling {
public:
    /// `culled`: GL_FRONT or GL_BACK; `front`: the winding of front-facing triangles, GL_CCW or GL_CW.
    FaceCulling(GLenum culled, GLenum front) {
        glFrontFace(front);
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
