#include "cutaway/colour_bar.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

#include <stb/stb_easy_font.h>

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

/// stb_easy_font quads (x, y, z, rgba per vertex) scaled by `scale` at (x, y) -> triangles.
void add_text(std::vector<BarVertex>& out, const std::string& text, float x, float y, float scale) {
    std::vector<char> buffer(text.size() * 300 + 64);
    std::string copy = text;
    std::uint8_t black[4] = {20, 20, 20, 255};
    const int quads = stb_easy_font_print(0, 0, copy.data(), black, buffer.data(), int(buffer.size()));
    struct FontVertex {
        float x, y, z;
        std::uint8_t c[4];
    };
    const auto* v = reinterpret_cast<const FontVertex*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
        const FontVertex* quad = v + 4 * q;
        auto at = [&](int k) {
            return BarVertex{x + scale * quad[k].x, y + scale * quad[k].y, {20, 20, 20, 255}, -1.0f};
        };
        out.insert(out.end(), {at(0), at(1), at(2), at(0), at(2), at(3)});
    }
}

std::string format_value(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", double(value));
    return text;
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
    const float scale = std::clamp(float(height) / 400.0f, 1.0f, 3.0f);  // text size follows the image
    const float bar_w = 10 * scale, bar_h = 0.4f * float(height);
    const float x1 = float(width) - 40 * scale, x0 = x1 - bar_w;
    const float y0 = 0.3f * float(height), y1 = y0 + bar_h;
    std::vector<BarVertex> vertices;
    const std::uint8_t frame[4] = {20, 20, 20, 255};
    add_rectangle(vertices, x0 - 1, y0 - 1, x1 + 1, y1 + 1, frame, -1, -1);
    add_rectangle(vertices, x0, y0, x1, y1, frame, 1.0f, 0.0f);
    // Labels end 4 pixels left of the bar (right-aligned); the name sits above, right-aligned too.
    const auto text_width = [&](const std::string& text) {
        std::string copy = text;
        return scale * float(stb_easy_font_width(copy.data()));
    };
    const std::string top = format_value(label.max), bottom = format_value(label.min);
    add_text(vertices, label.property, x1 - text_width(label.property), y0 - 14 * scale, scale);
    add_text(vertices, top, x0 - 4 * scale - text_width(top), y0 - 3 * scale, scale);
    add_text(vertices, bottom, x0 - 4 * scale - text_width(bottom), y1 - 3 * scale, scale);
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
