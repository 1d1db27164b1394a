#pragma once
// The perceptual colour map (matplotlib's viridis) as a 256-texel 1D texture and on the CPU.
#include <array>
#include <cstdint>

#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// RGBA8 1D texture, linear filtering.
gl::Texture make_colour_map_texture();

}  // namespace cutaway::pipeline
