#pragma once
// Move-only immutable-storage 3D texture (the GL layer's Texture covers 1D and 2D only).
#include "gl/gl_objects.h"

namespace cutaway::volume {

class Texture3D : public gl::GlObject<gl::TextureTraits> {
public:
    Texture3D() = default;
    /// width x height x depth texels of `internal_format`; nearest filtering, clamp to edge.
    Texture3D(GLenum internal_format, int width, int height, int depth);
    /// Whole-texture upload of tightly packed rows (unpack alignment 1).
    void upload(GLenum format, GLenum type, const void* data) const;
    void set_filter(GLenum filter) const;
    void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }
    int width() const { return width_; }
    int height() const { return height_; }
    int depth() const { return depth_; }

private:
    int width_ = 0, height_ = 0, depth_ = 0;
};

}  // namespace cutaway::volume
