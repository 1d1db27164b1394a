#include "volume/orientation_labels.h"

#include <algorithm>
#include <cmath>

#include "annotation/axis_ticks.h"
#include "volume/image_drawing.h"

namespace cutaway::volume {

namespace {

/// Pixel (y down) of voxel-space point `p`.
glm::vec2 to_pixels(const ViewGeometry& view, glm::vec3 p, int width, int height) {
    const glm::vec4 clip = view.voxel_to_clip * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(0.5f * ndc.x + 0.5f) * float(width), (0.5f - 0.5f * ndc.y) * float(height)};
}

/// `line` moved so that its ink is centred on `at`.
annotation::TextLine centred_at(annotation::TextLine line, glm::vec2 at) {
    const annotation::PixelRect ink = annotation::ink_box(line);
    line.x = std::round(at.x - 0.5f * (ink.x0 + ink.x1));
    line.y = std::round(at.y - 0.5f * (ink.y0 + ink.y1));
    return line;
}

bool inside(const annotation::PixelRect& r, float right_limit, int height) {
    return r.x0 >= 0 && r.y0 >= 0 && r.x1 <= right_limit && r.y1 <= float(height);
}

/// Share of an edge from its shared corner where inline and crossline values are left out: a value
/// there could belong to either edge.
constexpr double shared_corner_share = 0.12;

/// Ticks at round values of `span` (voxel indices 0 .. n - 1 when unknown) along `edge`, whose
/// voxel-space ends are `origin` and `end` on `axis`; labels clear of `placed` (which they join);
/// none near `origin` when another edge starts there too (`shared_origin`).
std::vector<AxisTick> edge_ticks(const ViewGeometry& view, int width, int height, float right_limit, float text_scale,
                                 int axis, glm::vec3 origin, SurveySpan span, glm::vec2 centre, bool shared_origin,
                                 std::vector<annotation::PixelRect>& placed) {
    const int voxels = int(std::lround(view.box[axis]));
    if (voxels < 1) return {};
    if (span.first == span.last) span = {0, double(voxels - 1)};
    const annotation::AxisTicks values =
        annotation::nice_ticks(std::min(span.first, span.last), std::max(span.first, span.last), 3);
    std::vector<AxisTick> ticks;
    for (std::size_t k = 0; k < values.values.size(); ++k) {
        // The value's voxel centre along the axis (voxel v spans [v, v + 1]).
        const double share = voxels > 1 ? (values.values[k] - span.first) / (span.last - span.first) : 0.0;
        glm::vec3 p = origin;
        p[axis] = float(share * double(voxels - 1) + 0.5);
        if (shared_origin && std::abs(p[axis] - origin[axis]) < shared_corner_share * view.box[axis]) continue;
        AxisTick tick;
        tick.value = values.values[k];
        tick.from = to_pixels(view, p, width, height);
        glm::vec3 q = p;
        q[axis] += 1.0f;
        glm::vec2 along = to_pixels(view, q, width, height) - tick.from;
        if (glm::length(along) == 0.0f) continue;
        glm::vec2 out{-along.y, along.x};
        out /= glm::length(out);
        if (glm::dot(out, tick.from - centre) < 0) out = -out;
        tick.to = tick.from + out * (3 * text_scale);
        tick.label = {values.labels[k], 0, 0, text_scale};
        const annotation::PixelRect ink = annotation::ink_box(tick.label);
        const float reach = 0.5f * std::abs(glm::dot(glm::vec2(ink.width(), ink.height()), glm::abs(out)));
        tick.label = centred_at(tick.label, tick.to + out * (2 * text_scale + reach));
        const annotation::PixelRect ink_box = annotation::ink_box(tick.label);
        // A glyph's width of room around each label: closer, a value beside an axis name or another
        // value reads as one ("crossline 25").
        const float room = 6 * text_scale;
        const annotation::PixelRect box{ink_box.x0 - room, ink_box.y0 - room, ink_box.x1 + room, ink_box.y1 + room};
        if (!inside(ink_box, right_limit, height) ||
            std::any_of(placed.begin(), placed.end(), [&](const annotation::PixelRect& r) { return r.overlaps(box); }))
            continue;
        placed.push_back(box);
        ticks.push_back(tick);
    }
    return ticks;
}

glm::vec3 box_corner(const ViewGeometry& view, int c) {
    return {c & 1 ? view.box.x : 0.0f, c & 2 ? view.box.y : 0.0f, c & 4 ? view.box.z : 0.0f};
}

/// The end, lower on screen, of the left-most of the cube's four edges along `axis`: an edge of
/// the cube's outline, so that its ticks and labels lie beside the data, not over it (the edge at
/// the lowest corner, the other axes' choice, runs down the cube's front for the vertical axis).
glm::vec3 left_edge_origin(const ViewGeometry& view, int axis, int width, int height) {
    glm::vec3 best(0);
    float best_x = 1e30f;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 a = box_corner(view, c);
        if (a[axis] != 0.0f) continue;
        glm::vec3 b = a;
        b[axis] = view.box[axis];
        const glm::vec2 pa = to_pixels(view, a, width, height), pb = to_pixels(view, b, width, height);
        if (const float x = 0.5f * (pa.x + pb.x); x < best_x) {
            best_x = x;
            best = pa.y >= pb.y ? a : b;
        }
    }
    return best;
}

}  // namespace

std::array<AxisEdge, 3> layout_orientation(const ViewGeometry& view, int width, int height, float right_limit,
                                           float text_scale, const SurveyAxes& axes) {
    // The corner lowest on screen: its edges run along the cube's visible bottom (inline and
    // crossline); time runs up the cube's left outline.
    glm::vec3 origin(0);
    float lowest = -1e30f;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner = box_corner(view, c);
        if (const float y = to_pixels(view, corner, width, height).y; y > lowest) {
            lowest = y;
            origin = corner;
        }
    }
    const glm::vec2 centre = to_pixels(view, 0.5f * view.box, width, height);
    const SurveySpan spans[3] = {axes.time_ms, axes.crossline, axes.inline_number};  // voxel axes x, y, z
    const char* names[3] = {axes.time_ms.first != axes.time_ms.last ? "time (ms)" : "time", "crossline", "inline"};
    const std::array<glm::vec3, 3> origins{left_edge_origin(view, 0, width, height), origin, origin};
    std::array<AxisEdge, 3> edges;
    for (int axis = 0; axis < 3; ++axis) {
        const glm::vec3 start = origins[std::size_t(axis)];
        glm::vec3 end = start;
        end[axis] = start[axis] > 0 ? 0.0f : view.box[axis];
        AxisEdge& edge = edges[std::size_t(axis)];
        edge.from = to_pixels(view, start, width, height);
        edge.to = to_pixels(view, end, width, height);
        // The label sits beyond the edge's far end, away from the cube's centre.
        glm::vec2 away = edge.to - centre;
        away = glm::length(away) > 0 ? away / glm::length(away) : glm::vec2(0, 1);
        edge.label = {names[axis], 0, 0, text_scale};
        const annotation::PixelRect ink = annotation::ink_box(edge.label);
        const glm::vec2 size{ink.width(), ink.height()};
        const glm::vec2 anchor = edge.to + away * (6 * text_scale + 0.5f * glm::length(size));
        const float margin = 2 * text_scale;
        edge.label.x = std::round(std::clamp(anchor.x - 0.5f * size.x, margin, std::max(margin, right_limit - margin - size.x)));
        edge.label.y = std::round(std::clamp(anchor.y - 0.5f * size.y, margin, float(height) - margin - size.y));
    }
    // Axis names with half a glyph's width of room of their own beside them: a value on a name's
    // line keeps one and a half glyphs from it (one reads as a word space: "crossline 25"), one
    // from another value (two glyphs left a 640 px F3 render's crossline a single value).
    std::vector<annotation::PixelRect> placed;
    const float name_room = 3 * text_scale;
    for (const AxisEdge& edge : edges) {
        const annotation::PixelRect ink = annotation::ink_box(edge.label);
        placed.push_back({ink.x0 - name_room, ink.y0, ink.x1 + name_room, ink.y1});
    }
    for (int axis = 0; axis < 3; ++axis) {
        const glm::vec3 start = origins[std::size_t(axis)];
        const bool shared = start == origin && axis > 0;
        std::vector<annotation::PixelRect> before = placed;
        std::vector<AxisTick> ticks = edge_ticks(view, width, height, right_limit, text_scale, axis, start, spans[axis], centre,
                                                 shared, placed);
        // A short edge that keeps fewer than two values away from the corner keeps its corner one.
        if (shared && ticks.size() < 2) {
            placed = std::move(before);
            ticks = edge_ticks(view, width, height, right_limit, text_scale, axis, start, spans[axis], centre, false, placed);
        }
        edges[std::size_t(axis)].ticks = std::move(ticks);
    }
    return edges;
}

void draw_orientation(gl::RgbaImage& image, const std::array<AxisEdge, 3>& edges, float line_width, Rgba ink) {
    for (const AxisEdge& edge : edges) {
        draw_line(image, edge.from, edge.to, line_width, ink);
        draw_text(image, edge.label, ink);
        for (const AxisTick& tick : edge.ticks) {
            draw_line(image, tick.from, tick.to, line_width, ink);
            draw_text(image, tick.label, ink);
        }
    }
}

}  // namespace cutaway::volume
