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

std::array<std::uint8_t, 3> colour_map_rgb(float t) {
    const float at = 255.0f * (colour_map_viridis_start + (1.0f - colour_map_viridis_start) * std::clamp(t, 0.0f, 1.0f));
    const int below = std::min(254, int(at));
    const float above_weight = at - float(below);
    std::array<std::uint8_t, 3> rgb{};
    for (std::size_t c = 0; c < 3; ++c)
        rgb[c] = std::uint8_t(std::lround((1.0f - above_weight) * viridis[below][c] + above_weight * viridis[below + 1][c]));
    return rgb;
}

gl::Texture make_colour_map_texture() {
    gl::Texture texture(GL_TEXTURE_1D, GL_RGBA8, 256);
    std::vector<std::uint8_t> texels(256 * 4);
    for (std::size_t i = 0; i < 256; ++i) {
        const std::array<std::uint8_t, 3> rgb = colour_map_rgb(float(i) / 255.0f);
        for (std::size_t c = 0; c < 3; ++c) texels[4 * i + c] = rgb[c];
        texels[4 * i + 3] = 255;
    }
    glTextureSubImage1D(texture.id(), 0, 0, 256, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    texture.set_filter(GL_LINEAR);
    return texture;
}

}  // namespace cutaway::pipeline
