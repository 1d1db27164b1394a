#pragma once
// Text as stb_easy_font draws it: one axis-aligned box per stroke, in image pixels.
#include <string>
#include <vector>

namespace cutaway::annotation {

/// Axis-aligned rectangle in image pixels: x to the right, y down from the top-left corner.
struct PixelRect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    float width() const { return x1 - x0; }
    float height() const { return y1 - y0; }
    bool overlaps(const PixelRect& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
    /// The smallest rectangle holding both (an empty `this`, x0 > x1, holds nothing).
    PixelRect united(const PixelRect& o) const;
};

/// An empty rectangle to unite others into.
PixelRect empty_rect();

/// One line of text: stb_easy_font's origin (top-left of the line) at (x, y), scaled by `scale`.
struct TextLine {
    std::string text;
    float x = 0;
    float y = 0;
    float scale = 1;
};

/// The strokes of every glyph of `line`, one rectangle each, in image pixels.
std::vector<PixelRect> glyph_boxes(const TextLine& line);

/// Width of `text` at `scale` (stb_easy_font's advance, pixels).
float text_width(const std::string& text, float scale);

/// Height of capital letters and digits at scale 1 (pixels); descenders go 2 pixels lower.
inline constexpr float cap_height_px = 7.0f;

/// The box around every stroke of `line` (empty_rect() for blank text).
PixelRect ink_box(const TextLine& line);

}  // namespace cutaway::annotation
