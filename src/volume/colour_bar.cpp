#include "volume/colour_bar.h"

#include <algorithm>
#include <cmath>

namespace cutaway::volume {

namespace {
void put(gl::RgbaImage& image, int x, int y, float r, float g, float b) {
    std::uint8_t* pixel = image.at(x, y);
    pixel[0] = std::uint8_t(std::lround(std::clamp(r, 0.0f, 1.0f) * 255));
    pixel[1] = std::uint8_t(std::lround(std::clamp(g, 0.0f, 1.0f) * 255));
    pixel[2] = std::uint8_t(std::lround(std::clamp(b, 0.0f, 1.0f) * 255));
    pixel[3] = 255;
}
}  // namespace

void draw_colour_bar(gl::RgbaImage& image, const TransferTable& table, Rgba background) {
    const int bar_width = std::max(8, image.width / 40) & ~1;
    const int bar_height = image.height * 3 / 5;
    const int margin = std::max(4, image.width / 64);
    const int x0 = image.width - margin - bar_width, y0 = (image.height - bar_height) / 2;
    if (x0 < 1 || y0 < 1) return;
    float max_alpha = 0;
    for (const Rgba& entry : table) max_alpha = std::max(max_alpha, entry.a);
    for (int row = 0; row < bar_height; ++row) {
        const float level = 255.0f * float(bar_height - 1 - row) / float(std::max(1, bar_height - 1));
        const Rgba c = lookup(table, level);
        const float shown = max_alpha > 0 ? c.a / max_alpha : 0;
        for (int col = 0; col < bar_width; ++col) {
            const float a = col < bar_width / 2 ? 1.0f : shown;
            put(image, x0 + col, y0 + row, c.r * a + background.r * (1 - a), c.g * a + background.g * (1 - a),
                c.b * a + background.b * (1 - a));
        }
    }
    for (int col = -1; col <= bar_width; ++col) {
        put(image, x0 + col, y0 - 1, 1, 1, 1);
        put(image, x0 + col, y0 + bar_height, 1, 1, 1);
    }
    for (int row = -1; row <= bar_height; ++row) {
        put(image, x0 - 1, y0 + row, 1, 1, 1);
        put(image, x0 + bar_width, y0 + row, 1, 1, 1);
    }
}

}  // namespace cutaway::volume
