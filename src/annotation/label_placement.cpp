#include "annotation/label_placement.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cutaway::annotation {
namespace {

PixelRect moved(const PixelRect& r, float dx, float dy) { return {r.x0 + dx, r.y0 + dy, r.x1 + dx, r.y1 + dy}; }

bool inside(const PixelRect& r, float x1, float y1) { return r.x0 >= 0 && r.y0 >= 0 && r.x1 <= x1 && r.y1 <= y1; }

/// The box shifted the least to lie inside [0, x1] x [0, y1] (one larger than that keeps its top left there).
PixelRect clamped(const PixelRect& r, float x1, float y1) {
    float dx = r.x1 > x1 ? x1 - r.x1 : 0.0f, dy = r.y1 > y1 ? y1 - r.y1 : 0.0f;
    if (r.x0 + dx < 0) dx = -r.x0;
    if (r.y0 + dy < 0) dy = -r.y0;
    return moved(r, dx, dy);
}

/// Candidate top-left offsets of a `w` x `h` box around its anchor, nearest first: right and left
/// of it, above and below, then the same ring farther out.
std::vector<std::pair<float, float>> candidate_offsets(float w, float h, float gap) {
    std::vector<std::pair<float, float>> offsets;
    for (int ring = 0; ring < 8; ++ring) {
        const float d = gap + float(ring) * h;
        offsets.insert(offsets.end(), {{d, -h - d}, {-w - d, -h - d}, {d, d}, {-w - d, d}, {-0.5f * w, -h - d}, {-0.5f * w, d},
                                       {d, -0.5f * h}, {-w - d, -0.5f * h}});
    }
    return offsets;
}

}  // namespace

float label_text_scale(int height, float min_text_px) {
    return std::max(1.0f, std::max(0.0201f * float(height), min_text_px) / cap_height_px);
}

std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests, int width, int height, float reserved_right,
                                      float min_text_px) {
    const float s = label_text_scale(height, min_text_px);
    const float pad = 2 * s, gap = 3 * s;
    const float x1 = std::max(1.0f, float(width) - reserved_right), y1 = float(height);
    std::vector<PlacedLabel> placed;
    for (std::size_t r = 0; r < requests.size(); ++r) {
        const LabelRequest& request = requests[r];
        if (!(request.anchor_x >= 0 && request.anchor_x < float(width) && request.anchor_y >= 0 && request.anchor_y < y1)) continue;
        // The box at the origin: the text's ink with a margin; the text's origin follows the box.
        const TextLine at_origin{request.text, 0, 0, s};
        const PixelRect ink = ink_box(at_origin);
        if (ink.x0 > ink.x1) continue;  // blank text
        const PixelRect box0{ink.x0 - pad, ink.y0 - pad, ink.x1 + pad, ink.y1 + pad};
        std::optional<PixelRect> chosen, fallback;
        for (const auto& [dx, dy] : candidate_offsets(box0.width(), box0.height(), gap)) {
            const PixelRect box = moved(box0, request.anchor_x + dx - box0.x0, request.anchor_y + dy - box0.y0);
            if (!inside(box, x1, y1)) continue;
            if (!fallback) fallback = box;
            if (std::none_of(placed.begin(), placed.end(), [&](const PlacedLabel& p) { return p.box.overlaps(box); })) {
                chosen = box;
                break;
            }
        }
        if (!chosen) chosen = fallback ? *fallback : clamped(moved(box0, request.anchor_x + gap, request.anchor_y + gap), float(width), y1);
        PlacedLabel label;
        label.box = *chosen;
        label.line = {request.text, chosen->x0 - box0.x0, chosen->y0 - box0.y0, s};
        label.anchor_x = request.anchor_x;
        label.anchor_y = request.anchor_y;
        label.request = r;
        placed.push_back(label);
    }
    return placed;
}

std::optional<PlacedLabel> place_caption(const std::string& text, int width, int height, float reserved_right,
                                         float min_text_px) {
    float s = label_text_scale(height, min_text_px);
    const PixelRect unit_ink = ink_box({text, 0, 0, 1});
    if (unit_ink.x0 > unit_ink.x1) return std::nullopt;  // blank text
    // Margin and padding at the full scale; the text shrinks to what is left of the width.
    const float pad = 2 * s, margin = 6 * s;
    const float room = std::max(1.0f, float(width) - reserved_right - 2 * margin - 2 * pad);
    s = std::min(s, room / std::max(1.0f, unit_ink.x1));
    PlacedLabel caption;
    caption.line = {text, margin + pad, margin + pad, s};
    const PixelRect ink = ink_box(caption.line);
    caption.box = {ink.x0 - pad, ink.y0 - pad, ink.x1 + pad, ink.y1 + pad};
    caption.anchor_x = caption.box.x0;
    caption.anchor_y = caption.box.y0;
    if (!inside(caption.box, float(width), float(height))) return std::nullopt;  // an image too small for text
    return caption;
}

}  // namespace cutaway::annotation
