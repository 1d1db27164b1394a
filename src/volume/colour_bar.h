#pragma once
// The transfer function drawn into the image's right margin: level 0 at the bottom, 255 at the top;
// the left half shows the colour, the right half the colour at the level's opacity relative to the
// table's largest (so low-opacity ramps stay visible) over the background. White frame.
#include "gl/image.h"
#include "volume/transfer_function.h"

namespace cutaway::volume {

void draw_colour_bar(gl::RgbaImage& image, const TransferTable& table, Rgba background);

}  // namespace cutaway::volume
