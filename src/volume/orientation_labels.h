#pragma once
// Which way the cube lies: inline and crossline along the edges from the corner lowest on screen,
// time up the cube's left outline, drawn as lines,
// labelled "inline", "crossline" and "time (ms)" at their far ends, with tick marks at round values
// of the survey's numbers along them.
#include <array>
#include <vector>

#include "annotation/text_glyphs.h"
#include "gl/image.h"
#include "volume/quantised_volume.h"
#include "volume/view_geometry.h"

namespace cutaway::volume {

struct AxisTick {
    double value = 0;            ///< in the survey's numbers (ms, crossline or inline number)
    glm::vec2 from{0}, to{0};    ///< the mark, from the edge outwards, image pixels
    annotation::TextLine label;  ///< the value beyond the mark
};

struct AxisEdge {
    glm::vec2 from{0}, to{0};    ///< image pixels, y down
    annotation::TextLine label;  ///< beyond `to`, inside the image and left of the colour bar
    std::vector<AxisTick> ticks;  ///< round values along the edge (annotation::nice_ticks)
};

/// The edges along time, crossline and inline (in that order), text at `text_scale`; labels kept
/// inside [0, right_limit) x [0, height). Ticks at round values of `axes` (voxel indices where a
/// span is unknown), marks pointing away from the cube; a tick whose label would leave that area or
/// come within a glyph's width of a label placed before it (one and a half beside an axis name) is left out,
/// and so are inline and crossline values at the corner the two edges share (where a value could
/// be either's) unless that leaves an edge fewer than two.
std::array<AxisEdge, 3> layout_orientation(const ViewGeometry& view, int width, int height, float right_limit,
                                           float text_scale, const SurveyAxes& axes = {});

void draw_orientation(gl::RgbaImage& image, const std::array<AxisEdge, 3>& edges, float line_width, Rgba ink);

}  // namespace cutaway::volume
