#pragma once
// The perceptual colour map (matplotlib's viridis) as a 256-texel 1D texture and on the CPU.
#include <array>
#include <cstdint>

#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// RGB bytes of the map at t in [0, 1] (clamped), nearest of 256 entries.
std::array<std::uint8_t, 3> colour_map_rgb(float t);

/// RGBA8 1D texture, linear filtering.
gl::Texture make_colour_map_texture();

}  // namespace cutaway::pipeline
