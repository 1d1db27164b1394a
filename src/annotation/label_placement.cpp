#include "annotation/label_placement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace cutaway::annotation {

std::array<float, 2> leader_end(const PixelRect& box, float x, float y) {
    return {std::clamp(x, box.x0, box.x1), std::clamp(y, box.y0, box.y1)};
}

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

bool contains(const PixelRect& r, float x, float y) { return x >= r.x0 && x <= r.x1 && y >= r.y0 && y <= r.y1; }

/// Whether the segment from (ax, ay) to (bx, by) passes through `r` (Liang-Barsky clipping).
bool segment_crosses(const PixelRect& r, float ax, float ay, float bx, float by) {
    float t0 = 0, t1 = 1;
    const float dx = bx - ax, dy = by - ay;
    const float p[4] = {-dx, dx, -dy, dy}, q[4] = {ax - r.x0, r.x1 - ax, ay - r.y0, r.y1 - ay};
    for (int e = 0; e < 4; ++e) {
        if (p[e] == 0) {
            if (q[e] < 0) return false;
            continue;
        }
        const float t = q[e] / p[e];
        if (p[e] < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

/// How badly `box` for request `r` sits among the labels `placed` before: 100 for each label it
/// overlaps (text over text is unreadable), 1 for each leader line crossing it or crossed by its
/// own leader and each other request's anchor it covers (a reader may pair name and well wrongly);
/// 100 for each of the `obstacles` it overlaps.
int conflicts(const PixelRect& box, std::size_t r, const std::vector<LabelRequest>& requests,
              const std::vector<PlacedLabel>& placed, const std::vector<PixelRect>& obstacles) {
    const LabelRequest& request = requests[r];
    const auto [ex, ey] = leader_end(box, request.anchor_x, request.anchor_y);
    int count = 0;
    for (const PlacedLabel& p : placed) {
        const auto [px, py] = leader_end(p.box, p.anchor_x, p.anchor_y);
        count += 100 * int(p.box.overlaps(box)) + int(segment_crosses(box, p.anchor_x, p.anchor_y, px, py)) +
                 int(segment_crosses(p.box, request.anchor_x, request.anchor_y, ex, ey));
    }
    for (std::size_t o = 0; o < requests.size(); ++o)
        count += int(o != r && contains(box, requests[o].anchor_x, requests[o].anchor_y));
    for (const PixelRect& obstacle : obstacles) count += 100 * int(obstacle.overlaps(box));
    return count;
}

/// A label's box and its conflicts among the other labels.
struct Choice {
    PixelRect box;
    int conflicts = 0;
};

/// The first of `boxes` (a label's candidates for request `r`) with the fewest conflicts among the
/// labels `placed`; none if `boxes` is empty.
std::optional<Choice> least_conflicting(const std::vector<PixelRect>& boxes, std::size_t r,
                                        const std::vector<LabelRequest>& requests, const std::vector<PlacedLabel>& placed,
                                        const std::vector<PixelRect>& obstacles) {
    std::optional<Choice> chosen;
    for (const PixelRect& box : boxes) {
        if (const int c = conflicts(box, r, requests, placed, obstacles); !chosen || c < chosen->conflicts) {
            chosen = Choice{box, c};
            if (c == 0) break;
        }
    }
    return chosen;
}

/// Passes of placing again the labels with conflicts (each moves a label only to fewer conflicts).
constexpr int relabel_passes = 4;

}  // namespace

float label_text_scale(int height, float min_text_px) {
    return std::max(1.0f, std::max(0.0201f * float(height), min_text_px) / cap_height_px);
}

std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests, int width, int height, float reserved_right,
                                      float min_text_px, const std::vector<PixelRect>& obstacles) {
    const float s = label_text_scale(height, min_text_px);
    const float pad = 2 * s, gap = 3 * s;
    const float x1 = std::max(1.0f, float(width) - reserved_right), y1 = float(height);
    std::vector<PlacedLabel> placed;
    std::vector<std::vector<PixelRect>> candidates;  // per placed label, its boxes inside the image, nearest first
    for (std::size_t r = 0; r < requests.size(); ++r) {
        const LabelRequest& request = requests[r];
        if (!(request.anchor_x >= 0 && request.anchor_x < float(width) && request.anchor_y >= 0 && request.anchor_y < y1)) continue;
        // The box at the origin: the text's ink with a margin; the text's origin follows the box.
        const TextLine at_origin{request.text, 0, 0, s};
        const PixelRect ink = ink_box(at_origin);
        if (ink.x0 > ink.x1) continue;  // blank text
        const PixelRect box0{ink.x0 - pad, ink.y0 - pad, ink.x1 + pad, ink.y1 + pad};
        std::vector<PixelRect> boxes;
        for (const auto& [dx, dy] : candidate_offsets(box0.width(), box0.height(), gap))
            if (const PixelRect box = moved(box0, request.anchor_x + dx - box0.x0, request.anchor_y + dy - box0.y0); inside(box, x1, y1))
                boxes.push_back(box);
        const std::optional<Choice> chosen = least_conflicting(boxes, r, requests, placed, obstacles);
        PlacedLabel label;
        label.box = chosen ? chosen->box : clamped(moved(box0, request.anchor_x + gap, request.anchor_y + gap), float(width), y1);
        label.line = {request.text, label.box.x0 - box0.x0, label.box.y0 - box0.y0, s};
        label.anchor_x = request.anchor_x;
        label.anchor_y = request.anchor_y;
        label.request = r;
        placed.push_back(label);
        candidates.push_back(std::move(boxes));
    }
    // Placed one after another, an early label may take the only clear spot of a later one (wellheads
    // along the image's edge); each label with a conflict is placed again among all the others, while
    // that lowers its conflicts (every move lowers their sum, so the passes end).
    for (int pass = 0; pass < relabel_passes; ++pass) {
        bool moved_any = false;
        for (std::size_t i = 0; i < placed.size(); ++i) {
            std::vector<PlacedLabel> others = placed;
            others.erase(others.begin() + std::ptrdiff_t(i));
            PlacedLabel& label = placed[i];
            const int now = conflicts(label.box, label.request, requests, others, obstacles);
            if (now == 0) continue;
            const std::optional<Choice> better = least_conflicting(candidates[i], label.request, requests, others, obstacles);
            if (!better || better->conflicts >= now) continue;
            label.line.x += better->box.x0 - label.box.x0;
            label.line.y += better->box.y0 - label.box.y0;
            label.box = better->box;
            moved_any = true;
        }
        if (!moved_any) break;
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
