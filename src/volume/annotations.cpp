#include "volume/annotations.h"

#include "annotation/colour_bar_layout.h"
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

}  // namespace cutaway::volume
