#pragma once
// Name labels next to points of an image (a well's name beside its wellhead): each label a box
// of text placed near its anchor, inside the image, clear of the labels placed before it.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "annotation/text_glyphs.h"

namespace cutaway::annotation {

struct LabelRequest {
    std::string text;
    float anchor_x = 0, anchor_y = 0;  ///< image pixels, y down
};

struct PlacedLabel {
    TextLine line;
    PixelRect box;  ///< the label's background: the text's ink with a margin
    float anchor_x = 0, anchor_y = 0;
    std::size_t request = 0;  ///< the request's index
};

/// Text scale of labels on an image `height` pixels tall: capitals 2% of the height (as the colour
/// bar's) or `min_text_px` if larger (the colour bar's --text-height), never below stb's 7 px.
float label_text_scale(int height, float min_text_px = 0);

/// Places each request whose anchor lies inside the `width` x `height` image (others get no
/// label): the first of a ring of positions around the anchor, at growing distances, whose box
/// lies inside the image (left of its `reserved_right` columns) and overlaps no label placed
/// before; if none does, the nearest one inside the image. Every box returned lies inside the image.
std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests, int width, int height,
                                      float reserved_right = 0, float min_text_px = 0);

/// A caption of the whole image (an animation frame's date and step): one line at its top-left
/// corner with a margin, at label_text_scale, shrunk to fit left of `reserved_right` columns if it
/// is wider. Nothing for blank text or an image too small to hold it; the box lies inside the image.
std::optional<PlacedLabel> place_caption(const std::string& text, int width, int height, float reserved_right = 0,
                                         float min_text_px = 0);

}  // namespace cutaway::annotation
