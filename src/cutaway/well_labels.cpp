#include "cutaway/well_labels.h"

#include <algorithm>

#include "annotation/label_placement.h"

namespace cutaway::pipeline {
namespace {

std::uint8_t channel(float value) { return std::uint8_t(glm::clamp(value, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

std::vector<annotation::PlacedLabel> well_label_layout(const std::vector<WellHead>& heads, const Camera& camera,
                                                       float reserved_right, float min_text_px, const std::string& caption) {
    std::vector<annotation::LabelRequest> requests;
    for (const WellHead& head : heads) {
        const glm::vec4 clip = camera.view_projection() * glm::vec4(head.position, 1.0f);
        // Behind the camera: no anchor (place_labels skips anchors outside the image).
        const glm::vec2 ndc = clip.w > 0 ? glm::vec2(clip) / clip.w : glm::vec2(-2.0f);
        requests.push_back({head.name, (0.5f * ndc.x + 0.5f) * float(camera.width), (0.5f - 0.5f * ndc.y) * float(camera.height)});
    }
    // The caption is placed as FrameCaption places it (the same reserved columns and text height).
    std::vector<annotation::PixelRect> obstacles;
    if (const auto box = annotation::place_caption(caption, camera.width, camera.height, reserved_right, min_text_px))
        obstacles.push_back(box->box);
    return annotation::place_labels(requests, camera.width, camera.height, reserved_right, min_text_px, obstacles);
}

void WellLabels::draw(const gl::Framebuffer& target, const std::vector<WellHead>& heads, const Camera& camera,
                      float reserved_right, float min_text_px, const std::string& caption) {
    const float scale = annotation::label_text_scale(camera.height, min_text_px);
    for (const annotation::PlacedLabel& label : well_label_layout(heads, camera, reserved_right, min_text_px, caption)) {
        // Text in the well's colour, darkened to read on the light box.
        const glm::vec3 ink = 0.75f * heads[label.request].colour;
        const Rgba8 text = {channel(ink.r), channel(ink.g), channel(ink.b), 255};
        const Rgba8 paper = {255, 255, 255, 210};
        const auto [end_x, end_y] = annotation::leader_end(label.box, label.anchor_x, label.anchor_y);
        batch_.add_segment(label.anchor_x, label.anchor_y, end_x, end_y, std::max(1.0f, 0.5f * scale), text);
        batch_.add_rectangle(label.box, paper);
        batch_.add_text(label.line, text);
    }
    batch_.draw(target, camera.width, camera.height, nullptr);
}

}  // namespace cutaway::pipeline
