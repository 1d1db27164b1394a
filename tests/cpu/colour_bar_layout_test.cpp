// The colour bar's layout (issue 15): every glyph inside the image, text at least 2% of the image
// height, at least 3 round tick values inside the range, labels that neither overlap each other
// nor the gradient, a title with its unit. Checked on the layout object every bar draws from.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "annotation/axis_ticks.h"
#include "annotation/colour_bar_layout.h"
#include "annotation/label_placement.h"
#include "annotation/property_units.h"

namespace cutaway::annotation {
namespace {

struct Size {
    int width, height;
};

// The figure sizes we render (quick and full runs, goldens, seismic squares, main job).
constexpr Size sizes[] = {{320, 180}, {320, 240}, {640, 640}, {1280, 720}, {1600, 900}, {1920, 1080}, {1000, 1000}};

// The labels the experiments show plus hard ones: long names, negative amplitudes, large
// permeabilities, tiny and constant ranges.
const ColourBarLabel labels[] = {
    {"PORO", 0.0951f, 0.2229f, "frac"},
    {"PERMX", 0.9659f, 4965.3f, "mD"},
    {"NTG", 0.0015f, 1.0f, "-"},
    {"SWAT step 3", 0.15f, 0.9f, "frac"},
    {"K (layer index; the model has no property)", 0, 59, ""},
    {"amplitude", -32767.0f, 32767.0f, ""},
    {"FIPNUM", 1, 3, ""},
    {"PRESSURE", 250.01f, 250.02f, "bar"},
    {"PORO", 0.2f, 0.2f, "frac"},
};

std::string describe(const ColourBarLabel& label, Size size) {
    return label.property + " [" + std::to_string(label.min) + ", " + std::to_string(label.max) + "] at " +
           std::to_string(size.width) + "x" + std::to_string(size.height);
}

TEST(ColourBarLayout, EveryGlyphLiesInsideTheImage) {
    for (const Size size : sizes)
        for (const ColourBarLabel& label : labels) {
            const ColourBarLayout layout = layout_colour_bar(label, size.width, size.height);
            for (const TextLine& line : layout.texts())
                for (const PixelRect& glyph : glyph_boxes(line)) {
                    EXPECT_GE(glyph.x0, 0) << line.text << " for " << describe(label, size);
                    EXPECT_GE(glyph.y0, 0) << line.text << " for " << describe(label, size);
                    EXPECT_LE(glyph.x1, float(size.width)) << line.text << " for " << describe(label, size);
                    EXPECT_LE(glyph.y1, float(size.height)) << line.text << " for " << describe(label, size);
                }
            const PixelRect bounds = layout.bounds();
            EXPECT_TRUE(bounds.x0 >= 0 && bounds.y0 >= 0 && bounds.x1 <= float(size.width) && bounds.y1 <= float(size.height))
                << describe(label, size);
        }
}

TEST(ColourBarLayout, EveryStrokeOfLongTextIsDrawn) {
    // The last glyph's strokes reach the text's advance width (less stb's 1 px spacing): none of
    // them dropped, as a too small vertex buffer once dropped the last stroke of "PORO".
    for (const std::string text : {"PORO", "[frac]", "K (layer index; the model has no property)", "0.0000001", "WWWWMMMM@@@@"}) {
        const PixelRect ink = ink_box({text, 0, 0, 2});
        EXPECT_GE(ink.x1, text_width(text, 2) - 2 * 2) << text;
    }
}

TEST(ColourBarLayout, AtLeastThreeRoundTicksInsideTheRange) {
    for (const Size size : sizes)
        for (const ColourBarLabel& label : labels) {
            const ColourBarLayout layout = layout_colour_bar(label, size.width, size.height);
            if (label.min == label.max) {
                ASSERT_EQ(layout.ticks.size(), 1u) << describe(label, size);  // a constant has one value to show
                continue;
            }
            ASSERT_GE(layout.ticks.size(), 3u) << describe(label, size);
            for (std::size_t t = 0; t < layout.ticks.size(); ++t) {
                const ColourBarTick& tick = layout.ticks[t];
                EXPECT_GE(tick.value, double(label.min)) << describe(label, size);
                EXPECT_LE(tick.value, double(label.max)) << describe(label, size);
                // The label reads back as the value (to the digits it prints) and its mark sits
                // on the gradient at that value.
                const double printed = std::stod(tick.label.text);
                const double spacing = t > 0 ? tick.value - layout.ticks[t - 1].value : layout.ticks[1].value - tick.value;
                EXPECT_NEAR(printed, tick.value, 1e-3 * spacing) << tick.label.text << " for " << describe(label, size);
                EXPECT_GE(tick.y, layout.gradient.y0 - 0.5f);
                EXPECT_LE(tick.y, layout.gradient.y1 + 0.5f);
                if (t > 0) {
                    EXPECT_GT(tick.value, layout.ticks[t - 1].value);
                    EXPECT_LT(tick.y, layout.ticks[t - 1].y);  // larger values higher up
                }
            }
        }
}

TEST(ColourBarLayout, LogarithmicScaleTicksEachDecadeEvenlySpaced) {
    // Permeability over 3.6 decades: a tick per power of ten, each labelled with its value, the
    // decades equally far apart on the bar (a linear bar would put 1, 10 and 100 within 5% of its
    // bottom). Half a pixel: the marks are placed at float rows, not rounded.
    ColourBarLabel label{"PERMX", 0.5f, 2000.0f, "mD"};
    label.log_scale = true;
    const ColourBarLayout layout = layout_colour_bar(label, 1000, 600);
    ASSERT_EQ(layout.ticks.size(), 4u);
    const char* expected[] = {"1", "10", "100", "1000"};
    for (std::size_t t = 0; t < layout.ticks.size(); ++t) EXPECT_EQ(layout.ticks[t].label.text, expected[t]);
    const float decade = layout.ticks[0].y - layout.ticks[1].y;
    EXPECT_GT(decade, 0.0f);
    for (std::size_t t = 1; t < layout.ticks.size(); ++t) EXPECT_NEAR(layout.ticks[t - 1].y - layout.ticks[t].y, decade, 0.5f);
    const float bar = layout.gradient.y1 - layout.gradient.y0;
    EXPECT_NEAR(layout.gradient.y1 - layout.ticks[0].y, bar * std::log10(1.0 / 0.5) / std::log10(2000.0 / 0.5), 0.5f);
    label.min = 0;  // no logarithm of 0
    EXPECT_THROW(layout_colour_bar(label, 1000, 600), std::invalid_argument);
}

TEST(ColourBarLayout, MarksThePrimaryRangeBesideTheGradient) {
    // The reader finds the primaries' values on the bar: a band left of the gradient from the
    // range's min to its max, inside the reserved width; clamped to the bar, and never thinner
    // than 3 text pixels (a range of one value still shows). Half a pixel: float rows.
    ColourBarLabel label{"PORO", 0.0f, 0.4f, "frac"};
    EXPECT_FALSE(layout_colour_bar(label, 1000, 600).primary_band);
    label.primary_range = ColourBarLabel::Span{0.3f, 0.5f};
    const ColourBarLayout layout = layout_colour_bar(label, 1000, 600);
    ASSERT_TRUE(layout.primary_band);
    const PixelRect band = *layout.primary_band;
    const float bar = layout.gradient.y1 - layout.gradient.y0;
    EXPECT_NEAR(band.y1, layout.gradient.y1 - 0.75f * bar, 0.5f);  // 0.3 of 0..0.4
    EXPECT_NEAR(band.y0, layout.gradient.y0, 0.5f);                  // 0.5 clamped to the top
    EXPECT_LE(band.x1, layout.frame.x0);
    EXPECT_GE(band.x0, 1000 - colour_bar_reserved_width(label, 1000, 600));
    label.primary_range = ColourBarLabel::Span{0.2f, 0.2f};
    const PixelRect thin = *layout_colour_bar(label, 1000, 600).primary_band;
    EXPECT_GE(thin.height(), 3 * layout.text_scale - 0.01f);
}

TEST(ColourBarLayout, TextIsLegibleAndNothingOverlaps) {
    for (const Size size : sizes)
        for (const ColourBarLabel& label : labels) {
            const ColourBarLayout layout = layout_colour_bar(label, size.width, size.height);
            // Issue 15: text at least 2% of the image height (capitals; stb_easy_font's are 7 px at scale 1).
            EXPECT_GE(cap_height_px * layout.text_scale, 0.02f * float(size.height)) << describe(label, size);
            const std::vector<TextLine> texts = layout.texts();
            for (std::size_t a = 0; a < texts.size(); ++a) {
                const PixelRect box = ink_box(texts[a]);
                EXPECT_FALSE(box.overlaps(layout.frame)) << texts[a].text << " on the gradient, " << describe(label, size);
                for (std::size_t b = a + 1; b < texts.size(); ++b)
                    EXPECT_FALSE(box.overlaps(ink_box(texts[b])))
                        << "'" << texts[a].text << "' and '" << texts[b].text << "' overlap, " << describe(label, size);
            }
        }
}

TEST(ColourBarLayout, TitleCarriesTheUnitWhenKnown) {
    const ColourBarLayout layout = layout_colour_bar({"PERMX", 1, 5000, property_unit("PERMX")}, 1920, 1080);
    std::string title;
    for (const TextLine& line : layout.title) title += (title.empty() ? "" : " ") + line.text;
    EXPECT_EQ(title, "PERMX [mD]");
    const ColourBarLayout unknown = layout_colour_bar({"FACIES", 1, 5, property_unit("FACIES")}, 1920, 1080);
    ASSERT_EQ(unknown.title.size(), 1u);
    EXPECT_EQ(unknown.title[0].text, "FACIES");
}

TEST(ColourBarLayout, ReservedWidthHoldsTheWholeBar) {
    for (const Size size : sizes)
        for (const ColourBarLabel& label : labels) {
            const float reserved = colour_bar_reserved_width(label, size.width, size.height);
            EXPECT_LT(float(size.width) - reserved, layout_colour_bar(label, size.width, size.height).bounds().x0)
                << describe(label, size);
        }
}

TEST(PropertyUnits, TheKeywordsOfOurModels) {
    EXPECT_EQ(property_unit("PORO"), "frac");
    EXPECT_EQ(property_unit("NTG"), "-");
    EXPECT_EQ(property_unit("PERMX"), "mD");
    EXPECT_EQ(property_unit("SWAT"), "frac");
    EXPECT_EQ(property_unit("NOT_A_KEYWORD"), "");
    EXPECT_EQ(property_unit("PRESSURE"), "bar");
    EXPECT_EQ(property_unit("PRESSURE", "FIELD"), "psia");
    EXPECT_EQ(property_unit("DEPTH", "FIELD"), "ft");
    EXPECT_EQ(property_unit("DX", "LAB"), "cm");
    EXPECT_EQ(property_unit("SWAT", "FIELD"), "frac");
}

TEST(AxisTicks, RoundStepsAndDigits) {
    const AxisTicks poro = nice_ticks(0.0951, 0.2229);
    EXPECT_EQ(poro.labels, (std::vector<std::string>{"0.10", "0.15", "0.20"}));
    const AxisTicks unit = nice_ticks(0, 1);
    EXPECT_EQ(unit.labels, (std::vector<std::string>{"0.0", "0.5", "1.0"}));
    const AxisTicks perm = nice_ticks(0.97, 4965);
    EXPECT_EQ(perm.labels, (std::vector<std::string>{"1000", "2000", "3000", "4000"}));
    const AxisTicks symmetric = nice_ticks(-3, 3);
    EXPECT_EQ(symmetric.labels, (std::vector<std::string>{"-2.5", "0.0", "2.5"}));
    EXPECT_THROW(nice_ticks(1, 0), std::invalid_argument);
    EXPECT_THROW(nice_ticks(0, NAN), std::invalid_argument);
}

// An animation frame's caption (place_caption): at the top left, inside the image and left of
// the colour bar's columns, shrunk rather than cut when the image is narrow; nothing to draw for
// blank text or an image too small for it.
TEST(FrameCaption, StaysInsideTheImageLeftOfTheColourBar) {
    const std::string text = "SWAT  2031-06-15  (step 2.5 of 0-30)";
    for (const Size size : {Size{1920, 1080}, Size{320, 180}, Size{120, 400}}) {
        const float reserved = 0.15f * float(size.width);
        const auto caption = place_caption(text, size.width, size.height, reserved);
        ASSERT_TRUE(caption.has_value()) << size.width << "x" << size.height;
        const PixelRect ink = ink_box(caption->line);
        EXPECT_GE(ink.x0, caption->box.x0);
        EXPECT_LE(ink.x1, caption->box.x1);
        EXPECT_GE(caption->box.x0, 0.0f);
        EXPECT_GE(caption->box.y0, 0.0f);
        EXPECT_LE(caption->box.x1, float(size.width) - reserved) << size.width << "x" << size.height;
        EXPECT_LE(caption->box.y1, 0.2f * float(size.height)) << "at the top";
    }
    // Wide enough: capitals 2% of the height, as the colour bar's; taller on request.
    EXPECT_FLOAT_EQ(place_caption(text, 1920, 1080)->line.scale, label_text_scale(1080));
    EXPECT_FLOAT_EQ(place_caption(text, 1920, 1080, 0, 40)->line.scale, 40 / cap_height_px);
    EXPECT_FALSE(place_caption("   ", 1920, 1080).has_value());
    EXPECT_FALSE(place_caption(text, 1920, 10).has_value());
}

}  // namespace
}  // namespace cutaway::annotation
