#include "volume/texture_3d.h"

namespace cutaway::volume {

namespace {
GLuint create_texture_3d() {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &name);
    return name;
}
}  // namespace

Texture3D::Texture3D(GLenum internal_format, int width, int height, int depth)
    : GlObject(create_texture_3d()), width_(width), height_(height), depth_(depth) {
    glTextureStorage3D(id(), 1, internal_format, width, height, depth);
    set_filter(GL_NEAREST);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(id(), wrap, GL_CLAMP_TO_EDGE);
}

void Texture3D::upload(GLenum format, GLenum type, const void* data) const {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage3D(id(), 0, 0, 0, 0, width_, height_, depth_, format, type, data);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

void Texture3D::set_filter(GLenum filter) const {
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(filter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(filter));
}

}  // namespace cutaway::volume
