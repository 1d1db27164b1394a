#include "volume/annotations.h"

#include <algorithm>

#include "annotation/colour_bar_layout.h"
#include "annotation/text_glyphs.h"
#include "volume/colour_bar.h"
#include "volume/image_drawing.h"
#include "volume/orientation_labels.h"

namespace cutaway::volume {

void draw_annotations(gl::RgbaImage& image, const VolumeScene& scene, const ViewGeometry& view, const RayCastSettings& settings) {
    const annotation::ColourBarLayout bar =
        annotation::layout_colour_bar(colour_bar_label(scene, settings.text_height_px), image.width, image.height);
    const float right_limit = bar.bounds().x0 - 2 * bar.text_scale;
    const std::array<AxisEdge, 3> edges =
        layout_orientation(view, image.width, image.height, right_limit, bar.text_scale, scene.volume->axes);
    draw_orientation(image, edges, std::max(1.0f, 0.5f * bar.text_scale), ink_on(settings.background));
    draw_colour_bar(image, scene, settings.background, settings.text_height_px);
}

void reserve_annotation_room(RayCastSettings& settings, const VolumeScene& scene) {
    if (!settings.colour_bar) return;
    const float width = float(settings.width);
    const annotation::ColourBarLabel label = colour_bar_label(scene, settings.text_height_px);
    settings.reserved_right_px = std::min(0.5f * width, annotation::colour_bar_reserved_width(label, settings.width, settings.height));
    // Four digits of time (ms) beside their marks (orientation_labels.cpp: a mark 3 units of the
    // text scale long, the value 2 beyond it) and a margin of 2.
    const float s = annotation::layout_colour_bar(label, settings.width, settings.height).text_scale;
    settings.reserved_left_px = std::min(0.25f * width, annotation::text_width("0000", s) + 7 * s);
}

}  // namespace cutaway::volume
