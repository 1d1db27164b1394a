#include "annotation/colour_bar_layout.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace cutaway::annotation {

namespace {

/// The bar's ticks: round values on a linear scale; on a logarithmic one each power of ten inside
/// the range when there are at least two of them, else round values (placed logarithmically).
AxisTicks colour_bar_ticks(const ColourBarLabel& label) {
    if (!label.log_scale) return nice_ticks(label.min, label.max);
    AxisTicks decades;
    for (double k = std::ceil(std::log10(double(label.min))); k <= std::floor(std::log10(double(label.max))); ++k) {
        std::ostringstream text;
        text << std::pow(10.0, k);
        decades.values.push_back(std::pow(10.0, k));
        decades.labels.push_back(text.str());
    }
    return decades.values.size() >= 2 ? decades : nice_ticks(label.min, label.max);
}

/// Where `value` lies along the bar, 0 (bottom, min) .. 1 (top, max).
double along_bar(const ColourBarLabel& label, double value) {
    const double lo = label.log_scale ? std::log10(double(label.min)) : double(label.min);
    const double hi = label.log_scale ? std::log10(double(label.max)) : double(label.max);
    const double at = label.log_scale ? std::log10(value) : value;
    return hi > lo ? (at - lo) / (hi - lo) : 0.5;
}

/// Words of `text` wrapped greedily into lines no wider than `max_width` (a longer word keeps its
/// own line).
std::vector<std::string> wrap_words(const std::string& text, float max_width, float scale) {
    std::istringstream words(text);
    std::vector<std::string> lines;
    std::string word;
    while (words >> word) {
        if (!lines.empty() && text_width(lines.back() + " " + word, scale) <= max_width)
            lines.back() += " " + word;
        else
            lines.push_back(word);
    }
    return lines;
}

}  // namespace

PixelRect ColourBarLayout::bounds() const {
    PixelRect box = frame;
    for (const TextLine& line : texts()) box = box.united(ink_box(line));
    for (const ColourBarTick& tick : ticks) box = box.united(tick.mark);
    if (primary_band) box = box.united(*primary_band);
    return box;
}

std::vector<TextLine> ColourBarLayout::texts() const {
    std::vector<TextLine> lines = title;
    for (const ColourBarTick& tick : ticks) lines.push_back(tick.label);
    return lines;
}

namespace {

/// The dark band left of the gradient over the primaries' range (clamped to the gradient), at least
/// 3 text pixels tall so a narrow range, or one beyond the bar's end, still shows.
PixelRect primary_band(const ColourBarLabel& label, const ColourBarLayout& layout, float gap, float bar_width) {
    const float s = layout.text_scale, bar_height = layout.gradient.height();
    const auto row = [&](float value) {
        const double clamped = std::clamp(double(value), double(label.min), double(label.max));
        return layout.gradient.y1 - float(along_bar(label, clamped)) * bar_height;
    };
    float top = row(label.primary_range->max), bottom = row(label.primary_range->min);
    const float least = 3 * s;
    if (bottom - top < least) {
        const float middle = 0.5f * (top + bottom);
        top = std::max(layout.gradient.y0, middle - 0.5f * least);
        bottom = std::min(layout.gradient.y1, top + least);
        top = bottom - least;
    }
    const float x1 = layout.frame.x0 - gap, x0 = x1 - 0.5f * bar_width;
    return PixelRect{x0, top, x1, bottom};
}

}  // namespace

ColourBarLayout layout_colour_bar(const ColourBarLabel& label, int width, int height) {
    if (!std::isfinite(label.min) || !std::isfinite(label.max) || label.min > label.max)
        throw std::invalid_argument("colour bar: expected a finite range min <= max, found [" + std::to_string(label.min) +
                                    ", " + std::to_string(label.max) + "]");
    if (label.log_scale && !(label.min > 0))
        throw std::invalid_argument("colour bar: a logarithmic scale needs a range above 0, found [" + std::to_string(label.min) +
                                    ", " + std::to_string(label.max) + "]");
    ColourBarLayout layout;
    // Capitals 2% of the image height (issue 15's minimum; more would take width from the model)
    // or the label's minimum if larger, never below stb's 7 px.
    const float s = std::max(1.0f, std::max(0.0201f * float(height), label.min_text_px) / cap_height_px);
    layout.text_scale = s;
    const float margin = 6 * s, gap = 3 * s, bar_width = 8 * s, mark_length = 3 * s;

    const AxisTicks ticks = colour_bar_ticks(label);
    float label_width = 0;
    for (const std::string& text : ticks.labels) label_width = std::max(label_width, text_width(text, s));

    // Right to left: margin, tick labels, gap, marks, gradient.
    const float gradient_x1 = std::round(float(width) - margin - label_width - gap - mark_length);
    layout.gradient.x1 = gradient_x1;
    layout.gradient.x0 = gradient_x1 - bar_width;

    // The title's lines (property, then the unit in brackets) wrap to the bar's width or the
    // widest word, right-aligned at the image margin.
    const float block_width = float(width) - margin - (layout.gradient.x0 - 1);
    std::string title = label.property;
    if (!label.unit.empty()) title += " [" + label.unit + "]";
    const float line_height = 10 * s;  // stb's 7 px capitals + descenders + 1 px
    std::vector<std::string> title_lines = wrap_words(title, block_width, s);
    float title_height = float(title_lines.size()) * line_height;

    // The gradient spans 45% of the height, centred, and moves down if the title needs the room.
    const float half_label = 0.5f * cap_height_px * s;
    float bar_height = 0.45f * float(height);
    float y0 = 0.5f * (float(height) - bar_height);
    const float title_top = y0 - gap - title_height;
    if (title_top < margin) {
        y0 += margin - title_top;
        bar_height = std::max(2 * line_height, float(height) - margin - half_label - y0);
        bar_height = std::min(bar_height, 0.45f * float(height));
    }
    y0 = std::round(y0);
    bar_height = std::round(bar_height);
    layout.gradient.y0 = y0;
    layout.gradient.y1 = y0 + bar_height;
    layout.frame = {layout.gradient.x0 - 1, layout.gradient.y0 - 1, layout.gradient.x1 + 1, layout.gradient.y1 + 1};

    float y = y0 - gap - title_height;
    for (const std::string& text : title_lines) {
        // A word wider than the image shrinks to fit (an absurd name must still stay inside).
        const float fit = (float(width) - 2 * margin) / std::max(1.0f, text_width(text, 1));
        TextLine line{text, 0, std::round(y), std::min(s, fit)};
        const PixelRect ink = ink_box(line);
        line.x = std::round(float(width) - margin - ink.x1);  // right-aligned ink
        layout.title.push_back(line);
        y += line_height;
    }

    for (std::size_t t = 0; t < ticks.values.size(); ++t) {
        const double value = ticks.values[t];
        const double along = along_bar(label, value);
        const float tick_y = layout.gradient.y1 - float(along) * bar_height;
        ColourBarTick tick;
        tick.value = value;
        tick.y = tick_y;
        tick.mark = {layout.gradient.x1, tick_y - 0.5f * s, layout.gradient.x1 + mark_length, tick_y + 0.5f * s};
        tick.label = {ticks.labels[t], std::round(tick.mark.x1 + gap), std::round(tick_y - half_label), s};
        layout.ticks.push_back(tick);
    }
    if (label.primary_range) layout.primary_band = primary_band(label, layout, gap, bar_width);
    return layout;
}

float colour_bar_reserved_width(const ColourBarLabel& label, int width, int height) {
    const ColourBarLayout layout = layout_colour_bar(label, width, height);
    return float(width) - layout.bounds().x0 + 6 * layout.text_scale;  // the bar's margin again, as a gap
}

}  // namespace cutaway::annotation
