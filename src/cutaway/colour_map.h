#pragma once
// The perceptual colour map: matplotlib's viridis without its darkest fifth, as a 256-texel 1D
// texture and on the CPU. Under the headlight's shading (down to 0.35 of a colour) viridis's
// near-black purple end turned black, so every cell at the low end of the range (connate water
// saturation, tight rock) lost its shape and its edges; from a fifth in, the map keeps its
// perceptual order and every colour stays readable when shaded.
#include <array>
#include <cstdint>

#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// Where the map starts in viridis (0 = its darkest entry, 1 = its brightest).
inline constexpr float colour_map_viridis_start = 0.2f;

/// The map's colour at `t` (0 = the colour range's min, 1 = its max; clamped), RGB 0..255,
/// interpolated linearly between viridis's 256 entries as the texture's linear filter does.
std::array<std::uint8_t, 3> colour_map_rgb(float t);

/// RGBA8 1D texture of colour_map_rgb at 256 evenly spaced t, linear filtering.
gl::Texture make_colour_map_texture();

}  // namespace cutaway::pipeline
