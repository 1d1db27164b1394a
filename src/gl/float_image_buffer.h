#pragma once
// A width x height float image in a buffer object (row-major, rows as a texture's: bottom to
// top) that compute passes read and write as an R32F imageBuffer. Depth textures cannot be bound
// as images, so their values move in and out through the buffer by pixel transfers (GL side:
// nothing is read back to the CPU). On llvmpipe (1920x1080, a loaded machine) nine image loads
// per pixel cost far less than nine texelFetch from a depth texture (fragment or compute), and
// the copies in and out cost less than that saves (src/cutaway/post/mean_filter.cpp).
#include "gl/gl_objects.h"

namespace cutaway::gl {

class FloatImageBuffer {
public:
    /// Storage for width x height floats, kept if the size is unchanged (contents then undefined).
    void resize(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    /// Copies a GL_DEPTH_COMPONENT32F texture of this size in.
    void read_depth(const Texture& depth) const;
    /// Copies this into a GL_DEPTH_COMPONENT32F texture of this size, after the shader writes
    /// before it (a pixel-buffer barrier).
    void write_depth(const Texture& depth) const;
    /// Binds the image as image unit `unit` (format r32f) with `access` (GL_READ_ONLY, ...).
    void bind_image(GLuint unit, GLenum access) const;
    /// Whether a row is a whole number of 4-pixel texels (the width is a multiple of 4).
    bool has_quad_view() const { return width_ % 4 == 0; }
    /// Binds the same image as rgba32f texels of 4 horizontally adjacent pixels (width / 4 per
    /// row; only if has_quad_view()): on llvmpipe an image load or store costs about the same
    /// whatever its size, so a pass that reads or writes 4 pixels at once makes a quarter of the calls.
    void bind_quad_image(GLuint unit, GLenum access) const;

private:
    int width_ = 0, height_ = 0;
    Buffer buffer_;
    BufferTexture view_;       ///< R32F texels of buffer_
    BufferTexture quad_view_;  ///< RGBA32F texels of buffer_, when has_quad_view()
};

}  // namespace cutaway::gl
