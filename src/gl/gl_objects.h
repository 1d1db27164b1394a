#pragma once
// Move-only RAII owners for every GL object (GL 4.5 direct state access). A moved-from object
// holds 0; destruction deletes the name. Nothing else in the code calls glDelete*.
#include <epoxy/gl.h>

#include <cstddef>
#include <span>
#include <utility>

namespace cutaway::gl {

/// Owns one GL name; `Traits` says how to delete it.
template <typename Traits>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint id) : id_(id) {}
    ~GlObject() { reset(); }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }

private:
    void reset() {
        if (id_ != 0) Traits::destroy(id_);
        id_ = 0;
    }
    GLuint id_ = 0;
};

struct BufferTraits { static void destroy(GLuint id) { glDeleteBuffers(1, &id); } };
struct TextureTraits { static void destroy(GLuint id) { glDeleteTextures(1, &id); } };
struct FramebufferTraits { static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); } };
struct VertexArrayTraits { static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); } };
struct QueryTraits { static void destroy(GLuint id) { glDeleteQueries(1, &id); } };
struct ShaderTraits { static void destroy(GLuint id) { glDeleteShader(id); } };
struct ProgramTraits { static void destroy(GLuint id) { glDeleteProgram(id); } };

/// Immutable-storage buffer object.
class Buffer : public GlObject<BufferTraits> {
public:
    Buffer() = default;
    /// `bytes` of storage initialised from `data` (may be null); `flags` as for glNamedBufferStorage.
    Buffer(std::size_t bytes, const void* data, GLbitfield flags = 0);
    template <typename T>
    static Buffer from(std::span<const T> values, GLbitfield flags = 0) {
        return Buffer(values.size_bytes(), values.data(), flags);
    }
    std::size_t size_bytes() const { return bytes_; }
    void bind_base(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }

private:
    std::size_t bytes_ = 0;
};

/// Immutable-storage 1D or 2D texture; nearest filtering and edge clamping unless changed.
class Texture : public GlObject<TextureTraits> {
public:
    Texture() = default;
    Texture(GLenum target, GLenum internal_format, int width, int height = 1, int levels = 1);
    int width() const { return width_; }
    int height() const { return height_; }
    GLenum internal_format() const { return format_; }
    void set_filter(GLenum filter) const;
    void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }

private:
    int width_ = 0;
    int height_ = 0;
    GLenum format_ = 0;
};

/// A buffer texture: `buffer`'s storage read as texels of `internal_format` (samplerBuffer).
/// The buffer must outlive it.
class BufferTexture : public GlObject<TextureTraits> {
public:
    BufferTexture() = default;
    BufferTexture(const Buffer& buffer, GLenum internal_format);
    /// The buffer's first `bytes` only (a narrower format over part of a buffer).
    BufferTexture(const Buffer& buffer, GLenum internal_format, std::size_t bytes);
    void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }
};

/// Framebuffer object; attachments are textures owned elsewhere.
class Framebuffer : public GlObject<FramebufferTraits> {
public:
    Framebuffer();
    void attach(GLenum attachment, const Texture& texture) const;
    /// Sets the draw buffers and checks completeness; throws GlError naming `label` if incomplete.
    void finish(std::span<const GLenum> draw_buffers, const char* label) const;
    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }
};

class VertexArray : public GlObject<VertexArrayTraits> {
public:
    VertexArray();
    void bind() const { glBindVertexArray(id()); }
};

class Query : public GlObject<QueryTraits> {
public:
    Query() = default;
    explicit Query(GLenum target);
};

class Shader : public GlObject<ShaderTraits> {
    using GlObject::GlObject;
};

class Program : public GlObject<ProgramTraits> {
public:
    using GlObject::GlObject;
    void use() const { glUseProgram(id()); }
    GLint uniform(const char* name) const { return glGetUniformLocation(id(), name); }
};

}  // namespace cutaway::gl
