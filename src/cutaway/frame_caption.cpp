#include "cutaway/frame_caption.h"

#include <algorithm>

#include "annotation/label_placement.h"

namespace cutaway::pipeline {

float caption_reserved_rows(const std::string& text, int width, int height, float reserved_right, float min_text_px) {
    const auto caption = annotation::place_caption(text, width, height, reserved_right, min_text_px);
    return caption ? caption->box.y1 + caption->box.y0 : 0.0f;
}

void FrameCaption::draw(const gl::Framebuffer& target, int width, int height, const std::string& text, float reserved_right,
                        float min_text_px) {
    const auto caption = annotation::place_caption(text, width, height, reserved_right, min_text_px);
    if (!caption) return;
    // An opaque box with a dark outline: a translucent one over the model's far corner showed the
    // corner lightened, a shape a reader took for the model's geometry.
    const float outline = std::max(1.0f, caption->line.scale);
    const annotation::PixelRect box = caption->box;
    batch_.add_rectangle(box, {60, 60, 60, 255});  // the outline, inside the box's padding
    // Light grey, not white: a box the colour of the background would read as a hole in the model.
    batch_.add_rectangle({box.x0 + outline, box.y0 + outline, box.x1 - outline, box.y1 - outline}, {232, 232, 232, 255});
    batch_.add_text(caption->line, {20, 20, 20, 255});
    batch_.draw(target, width, height, nullptr);
}

}  // namespace cutaway::pipeline
