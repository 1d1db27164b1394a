#include "cutaway/colour_bar.h"

#include <algorithm>
#include <vector>

#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

struct BarVertex {
    float x, y;
    std::uint8_t colour[4];
    float map_t;
};

/// Two triangles for an axis-aligned rectangle; map_t at the top and bottom (solid if < 0).
void add_rectangle(std::vector<BarVertex>& out, float x0, float y0, float x1, float y1, const std::uint8_t (&c)[4],
                   float t_top, float t_bottom) {
    const BarVertex a{x0, y0, {c[0], c[1], c[2], c[3]}, t_top}, b{x1, y0, {c[0], c[1], c[2], c[3]}, t_top};
    const BarVertex d{x0, y1, {c[0], c[1], c[2], c[3]}, t_bottom}, e{x1, y1, {c[0], c[1], c[2], c[3]}, t_bottom};
    out.insert(out.end(), {a, b, e, a, e, d});
}

/// Every stroke of `line` as two solid triangles.
void add_text(std::vector<BarVertex>& out, const annotation::TextLine& line, const std::uint8_t (&c)[4]) {
    for (const annotation::PixelRect& glyph : annotation::glyph_boxes(line))
        add_rectangle(out, glyph.x0, glyph.y0, glyph.x1, glyph.y1, c, -1, -1);
}

}  // namespace

ColourBar::ColourBar(const gl::ShaderLibrary& shaders)
    : program_(shaders.build({{GL_VERTEX_SHADER, "post/colour_bar.vert"}, {GL_FRAGMENT_SHADER, "post/colour_bar.frag"}})) {
    glEnableVertexArrayAttrib(vertex_array_.id(), 0);
    glEnableVertexArrayAttrib(vertex_array_.id(), 1);
    glEnableVertexArrayAttrib(vertex_array_.id(), 2);
    glVertexArrayAttribFormat(vertex_array_.id(), 0, 2, GL_FLOAT, GL_FALSE, offsetof(BarVertex, x));
    glVertexArrayAttribFormat(vertex_array_.id(), 1, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(BarVertex, colour));
    glVertexArrayAttribFormat(vertex_array_.id(), 2, 1, GL_FLOAT, GL_FALSE, offsetof(BarVertex, map_t));
    for (GLuint a = 0; a < 3; ++a) glVertexArrayAttribBinding(vertex_array_.id(), a, 0);
}

void ColourBar::draw(const gl::Framebuffer& target, int width, int height, const gl::Texture& colour_map,
                     const ColourBarLabel& label) {
    const annotation::ColourBarLayout layout = annotation::layout_colour_bar(label, width, height);
    std::vector<BarVertex> vertices;
    const std::uint8_t ink[4] = {20, 20, 20, 255};
    const annotation::PixelRect& f = layout.frame;
    const annotation::PixelRect& g = layout.gradient;
    add_rectangle(vertices, f.x0, f.y0, f.x1, f.y1, ink, -1, -1);
    add_rectangle(vertices, g.x0, g.y0, g.x1, g.y1, ink, 1.0f, 0.0f);
    for (const annotation::ColourBarTick& tick : layout.ticks)
        add_rectangle(vertices, tick.mark.x0, tick.mark.y0, tick.mark.x1, tick.mark.y1, ink, -1, -1);
    if (const auto& band = layout.primary_band) add_rectangle(vertices, band->x0, band->y0, band->x1, band->y1, ink, -1, -1);
    for (const annotation::TextLine& line : layout.texts()) add_text(vertices, line, ink);
    const gl::Buffer buffer(vertices.size() * sizeof(BarVertex), vertices.data());
    glVertexArrayVertexBuffer(vertex_array_.id(), 0, buffer.id(), 0, sizeof(BarVertex));
    target.bind();
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    gl::set_uniform(program_, "viewport_size", glm::vec2(float(width), float(height)));
    gl::set_uniform(program_, "colour_map", 0);
    colour_map.bind(0);
    program_.use();
    vertex_array_.bind();
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
    glEnable(GL_DEPTH_TEST);
}

}  // namespace cutaway::pipeline
