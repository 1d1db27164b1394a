#pragma once
// Name labels next to points of an image (a well's name beside its wellhead): each label a box
// of text placed near its anchor, inside the image, clear of the labels placed before it.
#include <array>
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

/// The point of `box` nearest to (x, y): where a leader line from the anchor (x, y) meets the label.
std::array<float, 2> leader_end(const PixelRect& box, float x, float y);

/// Text scale of labels on an image `height` pixels tall: capitals 2% of the height (as the colour
/// bar's) or `min_text_px` if larger (the colour bar's --text-height), never below stb's 7 px.
float label_text_scale(int height, float min_text_px = 0);

/// Places each request whose anchor lies inside the `width` x `height` image (others get no
/// label): the first of a ring of positions around the anchor, at growing distances, whose box
/// lies inside the image (left of its `reserved_right` columns), overlaps no label or leader line
/// placed before, covers no other request's anchor and whose own leader (anchor to the box's
/// nearest point) crosses no label placed before; where none is clear (crowded wells), the one
/// with the fewest such conflicts, overlapping labels last. Then each label left with a conflict is
/// placed again among all the others (an early label may have taken a later one's only clear
/// spot), while that lowers its conflicts. `obstacles`: boxes already drawn on the image (the
/// frame's caption) that labels keep clear of as of each other. Every box returned lies inside the
/// image.
std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests, int width, int height,
                                      float reserved_right = 0, float min_text_px = 0,
                                      const std::vector<PixelRect>& obstacles = {});

/// A caption of the whole image (an animation frame's date and step): one line at its top-left
/// corner with a margin, at label_text_scale, shrunk to fit left of `reserved_right` columns if it
/// is wider. Nothing for blank text or an image too small to hold it; the box lies inside the image.
std::optional<PlacedLabel> place_caption(const std::string& text, int width, int height, float reserved_right = 0,
                                         float min_text_px = 0);

}  // namespace cutaway::annotation
