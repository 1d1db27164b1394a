#pragma once
// 2D drawings onto the final image in window pixels (origin top left): solid or colour-mapped
// rectangles, text strokes and line segments, collected and drawn in one call, alpha blended over
// the image (its alpha kept). What the colour bar and the well labels are drawn with.
#include <cstdint>
#include <vector>

#include "annotation/text_glyphs.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

using Rgba8 = std::uint8_t[4];

class OverlayBatch {
public:
    explicit OverlayBatch(const gl::ShaderLibrary& shaders);

    /// A rectangle of colour `c`, or of the colour map from `t_top` at y0 to `t_bottom` at y1 when
    /// both are >= 0, its saturation times `saturation` (the saturation contrast's factors).
    void add_rectangle(const annotation::PixelRect& r, const Rgba8& c, float t_top = -1, float t_bottom = -1,
                       float saturation = 1);
    /// Every stroke of `line` in colour `c`.
    void add_text(const annotation::TextLine& line, const Rgba8& c);
    /// A segment from (x0, y0) to (x1, y1), `width` pixels wide.
    void add_segment(float x0, float y0, float x1, float y1, float width, const Rgba8& c);

    /// Draws what was added onto `target` (width x height) and empties the batch. `colour_map`: the
    /// texture colour-mapped rectangles read (may be null when none was added).
    void draw(const gl::Framebuffer& target, int width, int height, const gl::Texture* colour_map);

private:
    struct Vertex {
        float x, y;
        std::uint8_t colour[4];
        float map_t;
        float saturation;
    };
    std::vector<Vertex> vertices_;
    gl::Program program_;
    gl::VertexArray vertex_array_;
};

}  // namespace cutaway::pipeline
