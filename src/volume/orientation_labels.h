#pragma once
// Which way the cube lies: its three edges from the corner lowest on screen, drawn as lines and
// labelled "inline", "crossline" and "time" at their far ends.
#include <array>

#include "annotation/text_glyphs.h"
#include "gl/image.h"
#include "volume/view_geometry.h"

namespace cutaway::volume {

struct AxisEdge {
    glm::vec2 from{0}, to{0};    ///< image pixels, y down
    annotation::TextLine label;  ///< beyond `to`, inside the image and left of the colour bar
};

/// The edges along time, crossline and inline (in that order), text at `text_scale`; labels kept
/// inside [0, right_limit) x [0, height).
std::array<AxisEdge, 3> layout_orientation(const ViewGeometry& view, int width, int height, float right_limit,
                                           float text_scale);

void draw_orientation(gl::RgbaImage& image, const std::array<AxisEdge, 3>& edges, float line_width, Rgba ink);

}  // namespace cutaway::volume
