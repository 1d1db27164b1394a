#include "volume/orientation_labels.h"

#include <algorithm>

#include "volume/image_drawing.h"

namespace cutaway::volume {

namespace {

/// Pixel (y down) of voxel-space point `p`.
glm::vec2 to_pixels(const ViewGeometry& view, glm::vec3 p, int width, int height) {
    const glm::vec4 clip = view.voxel_to_clip * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(0.5f * ndc.x + 0.5f) * float(width), (0.5f - 0.5f * ndc.y) * float(height)};
}

}  // namespace

std::array<AxisEdge, 3> layout_orientation(const ViewGeometry& view, int width, int height, float right_limit,
                                           float text_scale) {
    // The corner lowest on screen: its edges run along the cube's visible bottom.
    glm::vec3 origin(0);
    float lowest = -1e30f;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner{c & 1 ? view.box.x : 0.0f, c & 2 ? view.box.y : 0.0f, c & 4 ? view.box.z : 0.0f};
        if (const float y = to_pixels(view, corner, width, height).y; y > lowest) {
            lowest = y;
            origin = corner;
        }
    }
    const glm::vec2 centre = to_pixels(view, 0.5f * view.box, width, height);
    static constexpr const char* names[3] = {"time", "crossline", "inline"};  // voxel axes x, y, z
    std::array<AxisEdge, 3> edges;
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 end = origin;
        end[axis] = origin[axis] > 0 ? 0.0f : view.box[axis];
        AxisEdge& edge = edges[std::size_t(axis)];
        edge.from = to_pixels(view, origin, width, height);
        edge.to = to_pixels(view, end, width, height);
        // The label sits beyond the edge's far end, away from the cube's centre.
        glm::vec2 away = edge.to - centre;
        away = glm::length(away) > 0 ? away / glm::length(away) : glm::vec2(0, 1);
        edge.label = {names[axis], 0, 0, text_scale};
        const annotation::PixelRect ink = annotation::ink_box(edge.label);
        const glm::vec2 size{ink.width(), ink.height()};
        const glm::vec2 anchor = edge.to + away * (6 * text_scale + 0.5f * glm::length(size));
        const float margin = 2 * text_scale;
        edge.label.x = std::round(std::clamp(anchor.x - 0.5f * size.x, margin, std::max(margin, right_limit - margin - size.x)));
        edge.label.y = std::round(std::clamp(anchor.y - 0.5f * size.y, margin, float(height) - margin - size.y));
    }
    return edges;
}

void draw_orientation(gl::RgbaImage& image, const std::array<AxisEdge, 3>& edges, float line_width, Rgba ink) {
    for (const AxisEdge& edge : edges) {
        draw_line(image, edge.from, edge.to, line_width, ink);
        draw_text(image, edge.label, ink);
    }
}

}  // namespace cutaway::volume
