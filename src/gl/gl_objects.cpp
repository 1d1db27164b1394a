#include "gl/gl_objects.h"

#include <string>

#include "gl/gl_error.h"

namespace cutaway::gl {

namespace {
GLuint create_name(void (*create)(GLsizei, GLuint*)) {
    GLuint id = 0;
    create(1, &id);
    return id;
}
}  // namespace

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags)
    : GlObject(create_name(glCreateBuffers)), bytes_(bytes) {
    // Zero-sized storage is an error in GL; keep one byte so empty selections still bind.
    glNamedBufferStorage(id(), GLsizeiptr(bytes == 0 ? 1 : bytes), bytes == 0 ? nullptr : data, flags);
}

Texture::Texture(GLenum target, GLenum internal_format, int width, int height, int levels)
    : width_(width), height_(height), format_(internal_format) {
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    static_cast<GlObject&>(*this) = GlObject(name);
    if (target == GL_TEXTURE_1D)
        glTextureStorage1D(id(), levels, internal_format, width);
    else
        glTextureStorage2D(id(), levels, internal_format, width, height);
    set_filter(GL_NEAREST);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

BufferTexture::BufferTexture(const Buffer& buffer, GLenum internal_format) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &name);
    static_cast<GlObject&>(*this) = GlObject(name);
    glTextureBuffer(id(), internal_format, buffer.id());
}

BufferTexture::BufferTexture(const Buffer& buffer, GLenum internal_format, std::size_t bytes) {
    GLuint name = 0;
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &name);
    static_cast<GlObject&>(*this) = GlObject(name);
    glTextureBufferRange(id(), internal_format, buffer.id(), 0, GLsizeiptr(bytes));
}

void Texture::set_filter(GLenum filter) const {
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(filter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(filter));
}

Framebuffer::Framebuffer() : GlObject(create_name(glCreateFramebuffers)) {}

void Framebuffer::attach(GLenum attachment, const Texture& texture) const {
    glNamedFramebufferTexture(id(), attachment, texture.id(), 0);
}

void Framebuffer::finish(std::span<const GLenum> draw_buffers, const char* label) const {
    glNamedFramebufferDrawBuffers(id(), GLsizei(draw_buffers.size()), draw_buffers.data());
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw GlError(std::string("framebuffer '") + label + "' is incomplete (GL status " +
                      std::to_string(status) + ")");
}

VertexArray::VertexArray() : GlObject(create_name(glCreateVertexArrays)) {}

Query::Query(GLenum target) {
    GLuint name = 0;
    glCreateQueries(target, 1, &name);
    static_cast<GlObject&>(*this) = GlObject(name);
}

}  // namespace cutaway::gl
