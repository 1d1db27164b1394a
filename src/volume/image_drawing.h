#pragma once
// Drawing annotations into an 8-bit image on the CPU: filled rectangles, lines, stb text.
#include <glm/glm.hpp>

#include "annotation/text_glyphs.h"
#include "gl/image.h"
#include "volume/transfer_function.h"

namespace cutaway::volume {

/// Fills the pixels whose centres lie in `rect` (clipped to the image) with `colour` (opaque).
void fill_rect(gl::RgbaImage& image, const annotation::PixelRect& rect, Rgba colour);

/// Every stroke of `line` in `colour`.
void draw_text(gl::RgbaImage& image, const annotation::TextLine& line, Rgba colour);

/// A line from `a` to `b` (pixels, y down), `width` pixels wide, clipped to the image.
void draw_line(gl::RgbaImage& image, glm::vec2 a, glm::vec2 b, float width, Rgba colour);

/// White text on a dark background, near-black on a light one.
Rgba ink_on(Rgba background);

}  // namespace cutaway::volume
