#include "cutaway/overlay_batch.h"

#include <cmath>
#include <cstddef>

#include "gl/uniforms.h"

namespace cutaway::pipeline {

OverlayBatch::OverlayBatch(const gl::ShaderLibrary& shaders)
    : program_(shaders.build({{GL_VERTEX_SHADER, "post/colour_bar.vert"}, {GL_FRAGMENT_SHADER, "post/colour_bar.frag"}})) {
    glEnableVertexArrayAttrib(vertex_array_.id(), 0);
    glEnableVertexArrayAttrib(vertex_array_.id(), 1);
    glEnableVertexArrayAttrib(vertex_array_.id(), 2);
    glEnableVertexArrayAttrib(vertex_array_.id(), 3);
    glVertexArrayAttribFormat(vertex_array_.id(), 0, 2, GL_FLOAT, GL_FALSE, offsetof(Vertex, x));
    glVertexArrayAttribFormat(vertex_array_.id(), 1, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(Vertex, colour));
    glVertexArrayAttribFormat(vertex_array_.id(), 2, 1, GL_FLOAT, GL_FALSE, offsetof(Vertex, map_t));
    glVertexArrayAttribFormat(vertex_array_.id(), 3, 1, GL_FLOAT, GL_FALSE, offsetof(Vertex, saturation));
    for (GLuint a = 0; a < 4; ++a) glVertexArrayAttribBinding(vertex_array_.id(), a, 0);
}

void OverlayBatch::add_rectangle(const annotation::PixelRect& r, const Rgba8& c, float t_top, float t_bottom,
                                 float saturation) {
    const auto v = [&](float x, float y, float t) { return Vertex{x, y, {c[0], c[1], c[2], c[3]}, t, saturation}; };
    const Vertex a = v(r.x0, r.y0, t_top), b = v(r.x1, r.y0, t_top), d = v(r.x0, r.y1, t_bottom), e = v(r.x1, r.y1, t_bottom);
    vertices_.insert(vertices_.end(), {a, b, e, a, e, d});
}

void OverlayBatch::add_text(const annotation::TextLine& line, const Rgba8& c) {
    for (const annotation::PixelRect& glyph : annotation::glyph_boxes(line)) add_rectangle(glyph, c);
}

void OverlayBatch::add_segment(float x0, float y0, float x1, float y1, float width, const Rgba8& c) {
    const float length = std::hypot(x1 - x0, y1 - y0);
    if (!(length > 0)) return;
    // Half the width across the segment on either side.
    const float nx = -(y1 - y0) / length * 0.5f * width, ny = (x1 - x0) / length * 0.5f * width;
    const auto v = [&](float x, float y) { return Vertex{x, y, {c[0], c[1], c[2], c[3]}, -1, 1}; };
    vertices_.insert(vertices_.end(), {v(x0 + nx, y0 + ny), v(x1 + nx, y1 + ny), v(x1 - nx, y1 - ny), v(x0 + nx, y0 + ny),
                                       v(x1 - nx, y1 - ny), v(x0 - nx, y0 - ny)});
}

void OverlayBatch::draw(const gl::Framebuffer& target, int width, int height, const gl::Texture* colour_map) {
    if (vertices_.empty()) return;
    const gl::Buffer buffer(vertices_.size() * sizeof(Vertex), vertices_.data());
    glVertexArrayVertexBuffer(vertex_array_.id(), 0, buffer.id(), 0, sizeof(Vertex));
    target.bind();
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    // Colour over the image by the overlay's alpha; the image's alpha stays (an opaque PNG).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl::set_uniform(program_, "viewport_size", glm::vec2(float(width), float(height)));
    gl::set_uniform(program_, "colour_map", 0);
    if (colour_map) colour_map->bind(0);
    program_.use();
    vertex_array_.bind();
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices_.size()));
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    vertices_.clear();
}

}  // namespace cutaway::pipeline
