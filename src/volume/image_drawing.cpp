#include "volume/image_drawing.h"

#include <algorithm>
#include <cmath>

namespace cutaway::volume {

namespace {
void put(gl::RgbaImage& image, int x, int y, Rgba c) {
    std::uint8_t* pixel = image.at(x, y);
    pixel[0] = std::uint8_t(std::lround(std::clamp(c.r, 0.0f, 1.0f) * 255));
    pixel[1] = std::uint8_t(std::lround(std::clamp(c.g, 0.0f, 1.0f) * 255));
    pixel[2] = std::uint8_t(std::lround(std::clamp(c.b, 0.0f, 1.0f) * 255));
    pixel[3] = 255;
}
}  // namespace

void fill_rect(gl::RgbaImage& image, const annotation::PixelRect& rect, Rgba colour) {
    // Pixel (x, y) covers [x, x + 1): its centre x + 0.5 inside [x0, x1).
    const int x0 = std::max(0, int(std::ceil(rect.x0 - 0.5f))), x1 = std::min(image.width, int(std::ceil(rect.x1 - 0.5f)));
    const int y0 = std::max(0, int(std::ceil(rect.y0 - 0.5f))), y1 = std::min(image.height, int(std::ceil(rect.y1 - 0.5f)));
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) put(image, x, y, colour);
}

void draw_text(gl::RgbaImage& image, const annotation::TextLine& line, Rgba colour) {
    for (const annotation::PixelRect& glyph : annotation::glyph_boxes(line)) fill_rect(image, glyph, colour);
}

void draw_line(gl::RgbaImage& image, glm::vec2 a, glm::vec2 b, float width, Rgba colour) {
    const int steps = int(std::ceil(glm::length(b - a))) + 1;
    const float half = 0.5f * width;
    for (int s = 0; s <= steps; ++s) {
        const glm::vec2 p = a + (b - a) * (float(s) / float(steps));
        fill_rect(image, {p.x - half, p.y - half, p.x + half, p.y + half}, colour);
    }
}

Rgba ink_on(Rgba background) {
    const float luminance = 0.2126f * background.r + 0.7152f * background.g + 0.0722f * background.b;
    return luminance < 0.5f ? Rgba{1, 1, 1, 1} : Rgba{0.08f, 0.08f, 0.08f, 1};
}

}  // namespace cutaway::volume
