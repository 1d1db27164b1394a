#include "cutaway/colour_bar.h"

#include <cmath>

namespace cutaway::pipeline {

ColourBar::ColourBar(const gl::ShaderLibrary& shaders) : batch_(shaders) {}

void ColourBar::draw(const gl::Framebuffer& target, int width, int height, const gl::Texture& colour_map,
                     const ColourBarLabel& label, const std::optional<BarSaturation>& saturation) {
    const annotation::ColourBarLayout layout = annotation::layout_colour_bar(label, width, height);
    const Rgba8 ink = {20, 20, 20, 255};
    batch_.add_rectangle(layout.frame, ink);
    if (saturation) {
        annotation::PixelRect left = layout.gradient, right = layout.gradient;
        left.x1 = right.x0 = std::floor(0.5f * (layout.gradient.x0 + layout.gradient.x1));
        batch_.add_rectangle(left, ink, 1.0f, 0.0f, saturation->primaries);
        batch_.add_rectangle(right, ink, 1.0f, 0.0f, saturation->secondaries);
    } else {
        batch_.add_rectangle(layout.gradient, ink, 1.0f, 0.0f);
    }
    for (const annotation::ColourBarTick& tick : layout.ticks) batch_.add_rectangle(tick.mark, ink);
    if (const auto& band = layout.primary_band) batch_.add_rectangle(*band, ink);
    for (const annotation::TextLine& line : layout.texts()) batch_.add_text(line, ink);
    batch_.draw(target, width, height, &colour_map);
}

}  // namespace cutaway::pipeline
