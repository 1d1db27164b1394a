#include "cutaway/well_labels.h"

#include <algorithm>

#include "annotation/label_placement.h"

namespace cutaway::pipeline {
namespace {

std::uint8_t channel(float value) { return std::uint8_t(glm::clamp(value, 0.0f, 1.0f) * 255.0f + 0.5f); }

/// Points tried along a well's first segment for an anchor in view (1/64 of it apart).
constexpr int anchor_steps = 64;

/// Image pixel (y down) of render-space `p`; far outside the image behind the camera.
glm::vec2 image_point(const Camera& camera, const glm::vec3& p) {
    const glm::vec4 clip = camera.view_projection() * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = clip.w > 0 ? glm::vec2(clip) / clip.w : glm::vec2(-2.0f);
    return {(0.5f * ndc.x + 0.5f) * float(camera.width), (0.5f - 0.5f * ndc.y) * float(camera.height)};
}

/// Inside the image, a label's text height from its top edge (a name needs room above its anchor).
bool inside_image(const Camera& camera, const glm::vec2& p) {
    return p.x >= 0 && p.x < float(camera.width) && p.y >= 0.02f * float(camera.height) && p.y < float(camera.height);
}

}  // namespace

std::vector<annotation::PlacedLabel> well_label_layout(const std::vector<WellHead>& heads, const Camera& camera,
                                                       float reserved_right, float min_text_px, const std::string& caption) {
    std::vector<annotation::LabelRequest> requests;
    for (const WellHead& head : heads) {
        // The wellhead, or where the well's first segment comes into view when the head stands
        // above the framed model (a tall well's head left the image and its name with it).
        glm::vec2 anchor = image_point(camera, head.position);
        for (int step = 1; step <= anchor_steps && !inside_image(camera, anchor); ++step)
            anchor = image_point(camera, glm::mix(head.position, head.next, float(step) / float(anchor_steps)));
        requests.push_back({head.name, anchor.x, anchor.y});
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
