#pragma once
// Where the colour bar of a frame goes: the gradient, its tick marks and labels and its title,
// in image pixels. Computed on the CPU so that the GL bar (src/cutaway/colour_bar.cpp), the
// seismic bar (src/volume/colour_bar.cpp), the camera's framing and the tests share one layout.
#include <optional>
#include <string>
#include <vector>

#include "annotation/axis_ticks.h"
#include "annotation/text_glyphs.h"

namespace cutaway::annotation {

/// What the bar shows: a title (the property, e.g. "PORO" or "SWAT step 2"), its unit ("" when
/// unknown) and the values at the bottom and the top of the gradient.
struct ColourBarLabel {
    std::string property;
    float min = 0;
    float max = 1;
    std::string unit;
    /// Colours by log10 of the value between log10(min) and log10(max) (min > 0); ticks at round
    /// values of log10, labelled with the values themselves.
    bool log_scale = false;
    /// The primaries' value range, marked beside the gradient (clamped to it); none when the
    /// primaries are chosen otherwise (by a second property) or the range changes (the viewer).
    struct Span {
        float min = 0;
        float max = 0;
    };
    std::optional<Span> primary_range{};
    /// Capitals at least this tall, pixels (0: 2% of the image height): a figure printed smaller
    /// than its pixels asks for more so its text stays legible (7 pt at the printed width).
    float min_text_px = 0;
};

struct ColourBarTick {
    double value = 0;
    float y = 0;       ///< pixel row of the value on the gradient
    PixelRect mark;    ///< the tick mark, right of the gradient
    TextLine label;    ///< right of the mark
};

struct ColourBarLayout {
    PixelRect gradient;              ///< the colour map, bottom = min, top = max
    PixelRect frame;                 ///< one pixel around the gradient
    std::vector<TextLine> title;     ///< the title's lines, above the gradient
    std::vector<ColourBarTick> ticks;
    /// ColourBarLabel::primary_range: a dark band left of the gradient from its min to its max (at
    /// least 3 text pixels tall, so a narrow range, or one beyond the bar's end, still shows).
    std::optional<PixelRect> primary_band;
    float text_scale = 1;            ///< stb_easy_font scale of every text
    /// Every pixel the bar may draw (frame, marks, glyphs), plus no margin.
    PixelRect bounds() const;
    /// Every line of text: title lines then tick labels.
    std::vector<TextLine> texts() const;
};

/// The bar at the right edge of a `width` x `height` image: text at least 2% of the height,
/// everything inside the image with a margin, at least 3 round tick values (one for a constant
/// range). Throws std::invalid_argument for a non-finite or reversed range.
ColourBarLayout layout_colour_bar(const ColourBarLabel& label, int width, int height);

/// Pixels at the image's right edge the model must leave free for the bar of `label` (the bar's
/// width, its margin and a gap to the model).
float colour_bar_reserved_width(const ColourBarLabel& label, int width, int height);

}  // namespace cutaway::annotation
