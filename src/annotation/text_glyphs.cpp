#include "annotation/text_glyphs.h"

#include <algorithm>
#include <limits>

#include <stb/stb_easy_font.h>

namespace cutaway::annotation {

namespace {
/// stb_easy_font indexes its table by character - 32: anything outside printable ASCII is '?'.
std::string printable(const std::string& text) {
    std::string out = text;
    for (char& c : out)
        if (c < 32 || c > 126) c = '?';
    return out;
}
}  // namespace

PixelRect PixelRect::united(const PixelRect& o) const {
    return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
}

PixelRect empty_rect() {
    constexpr float big = std::numeric_limits<float>::max();
    return {big, big, -big, -big};
}

std::vector<PixelRect> glyph_boxes(const TextLine& line) {
    // stb_easy_font writes 4 vertices (x, y, z, rgba) of 16 bytes per stroke and silently drops
    // the strokes that do not fit (what clipped "PORO" to "PORC"): room for 32 strokes a glyph.
    std::vector<char> buffer(line.text.size() * 32 * 64 + 64);
    std::string copy = printable(line.text);
    unsigned char colour[4] = {0, 0, 0, 255};
    const int quads = stb_easy_font_print(0, 0, copy.data(), colour, buffer.data(), int(buffer.size()));
    struct FontVertex {
        float x, y, z;
        unsigned char rgba[4];
    };
    const auto* vertices = reinterpret_cast<const FontVertex*>(buffer.data());
    std::vector<PixelRect> boxes;
    boxes.reserve(std::size_t(quads));
    for (int q = 0; q < quads; ++q) {
        const FontVertex* v = vertices + 4 * q;  // corners 0 and 2 are opposite
        boxes.push_back({line.x + line.scale * std::min(v[0].x, v[2].x), line.y + line.scale * std::min(v[0].y, v[2].y),
                         line.x + line.scale * std::max(v[0].x, v[2].x), line.y + line.scale * std::max(v[0].y, v[2].y)});
    }
    return boxes;
}

float text_width(const std::string& text, float scale) {
    std::string copy = printable(text);
    return scale * float(stb_easy_font_width(copy.data()));
}

PixelRect ink_box(const TextLine& line) {
    PixelRect box = empty_rect();
    for (const PixelRect& glyph : glyph_boxes(line)) box = box.united(glyph);
    return box;
}

}  // namespace cutaway::annotation
