#include "cutaway/frame_caption.h"

#include "annotation/label_placement.h"

namespace cutaway::pipeline {

void FrameCaption::draw(const gl::Framebuffer& target, int width, int height, const std::string& text, float reserved_right,
                        float min_text_px) {
    const auto caption = annotation::place_caption(text, width, height, reserved_right, min_text_px);
    if (!caption) return;
    batch_.add_rectangle(caption->box, {255, 255, 255, 210});
    batch_.add_text(caption->line, {20, 20, 20, 255});
    batch_.draw(target, width, height, nullptr);
}

}  // namespace cutaway::pipeline
