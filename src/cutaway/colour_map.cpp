#include "cutaway/colour_map.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cutaway::pipeline {
namespace {

constexpr std::uint8_t viridis[256][3] = {
#include "annotation/viridis_table.inc"
};

}  // namespace

gl::Texture make_colour_map_texture() {
    gl::Texture texture(GL_TEXTURE_1D, GL_RGBA8, 256);
    std::vector<std::uint8_t> texels(256 * 4);
    for (std::size_t i = 0; i < 256; ++i) {
        for (std::size_t c = 0; c < 3; ++c) texels[4 * i + c] = viridis[i][c];
        texels[4 * i + 3] = 255;
    }
    glTextureSubImage1D(texture.id(), 0, 0, 256, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    texture.set_filter(GL_LINEAR);
    return texture;
}

}  // namespace cutaway::pipeline
