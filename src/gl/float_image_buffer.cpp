#include "gl/float_image_buffer.h"

#include <stdexcept>
#include <string>

namespace cutaway::gl {
namespace {

void check_size(const Texture& texture, int width, int height, const char* what) {
    if (texture.width() != width || texture.height() != height)
        throw std::invalid_argument(std::string(what) + ": texture " + std::to_string(texture.width()) + "x" +
                                    std::to_string(texture.height()) + ", image buffer " + std::to_string(width) + "x" +
                                    std::to_string(height));
}

}  // namespace

void FloatImageBuffer::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    view_ = BufferTexture();  // before the storage they view
    quad_view_ = BufferTexture();
    buffer_ = Buffer(std::size_t(width) * std::size_t(height) * sizeof(float), nullptr);
    view_ = BufferTexture(buffer_, GL_R32F);
    width_ = width;
    height_ = height;
    if (has_quad_view()) quad_view_ = BufferTexture(buffer_, GL_RGBA32F);
}

void FloatImageBuffer::read_depth(const Texture& depth) const {
    check_size(depth, width_, height_, "FloatImageBuffer::read_depth");
    glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.id());
    glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(buffer_.size_bytes()), nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
}

void FloatImageBuffer::write_depth(const Texture& depth) const {
    check_size(depth, width_, height_, "FloatImageBuffer::write_depth");
    glMemoryBarrier(GL_PIXEL_BUFFER_BARRIER_BIT);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, buffer_.id());
    glTextureSubImage2D(depth.id(), 0, 0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

void FloatImageBuffer::bind_image(GLuint unit, GLenum access) const {
    glBindImageTexture(unit, view_.id(), 0, GL_FALSE, 0, access, GL_R32F);
}

void FloatImageBuffer::bind_quad_image(GLuint unit, GLenum access) const {
    if (!has_quad_view())
        throw std::logic_error("FloatImageBuffer::bind_quad_image: width " + std::to_string(width_) + " is not a multiple of 4");
    glBindImageTexture(unit, quad_view_.id(), 0, GL_FALSE, 0, access, GL_RGBA32F);
}

}  // namespace cutaway::gl
