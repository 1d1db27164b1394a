#include "volume/colour_bar.h"

#include <algorithm>

#include "annotation/colour_bar_layout.h"
#include "volume/image_drawing.h"
#include "volume/level_window.h"

namespace cutaway::volume {

annotation::ColourBarLabel colour_bar_label(const VolumeScene& scene, float min_text_px) {
    // SEG-Y amplitudes carry no unit we can trust (trace header units are rarely filled in).
    annotation::ColourBarLabel label{"amplitude", float(level_value(scene.window.lo, scene.volume->range)),
                                     float(level_value(scene.window.hi, scene.volume->range)), ""};
    label.min_text_px = min_text_px;
    return label;
}

void draw_colour_bar(gl::RgbaImage& image, const VolumeScene& scene, Rgba background, float min_text_px) {
    const annotation::ColourBarLayout layout =
        annotation::layout_colour_bar(colour_bar_label(scene, min_text_px), image.width, image.height);
    const Rgba ink = ink_on(background);
    float max_alpha = 0;
    for (const Rgba& entry : scene.table) max_alpha = std::max(max_alpha, entry.a);
    fill_rect(image, layout.frame, ink);
    const annotation::PixelRect& g = layout.gradient;
    for (float y = g.y0; y < g.y1; ++y) {
        const float along = (g.y1 - (y + 0.5f)) / g.height();  // 0 at the bottom
        const float level = float(scene.window.lo + along * (scene.window.hi - scene.window.lo));
        const Rgba c = lookup(scene.table, level);
        const float shown = max_alpha > 0 ? c.a / max_alpha : 0;
        const Rgba faded{c.r * shown + background.r * (1 - shown), c.g * shown + background.g * (1 - shown),
                         c.b * shown + background.b * (1 - shown), 1};
        const float middle = 0.5f * (g.x0 + g.x1);
        fill_rect(image, {g.x0, y, middle, y + 1}, c);
        fill_rect(image, {middle, y, g.x1, y + 1}, faded);
    }
    for (const annotation::ColourBarTick& tick : layout.ticks) fill_rect(image, tick.mark, ink);
    for (const annotation::TextLine& line : layout.texts()) draw_text(image, line, ink);
}

}  // namespace cutaway::volume
