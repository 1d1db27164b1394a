#pragma once
// The `--cell-ids` image: each pixel's Eclipse cell index + 1 (0 = no cell) as a 32-bit value in
// an RGBA8 PNG, value = R + 256 G + 65536 B + 16777216 A (DESIGN.md, `cutaway render`).
#include <cstdint>
#include <vector>

#include "gl/image.h"

namespace cutaway::pipeline {

/// `ids`: width x height values, rows bottom to top (as GL reads them).
gl::RgbaImage encode_cell_ids(const std::vector<std::uint32_t>& ids, int width, int height);
/// The values of an encoded image, rows bottom to top again.
std::vector<std::uint32_t> decode_cell_ids(const gl::RgbaImage& image);

}  // namespace cutaway::pipeline
