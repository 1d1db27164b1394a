#pragma once
// How a GPU jump flooding pass of one step covers the image (gpu_jump_flooding.cpp,
// shaders/cut_surface/jump_flood.comp): invocations flood blocks of pixels one step apart, 2 along
// an axis where a pixel has a partner a step further in the same span of 2 x step pixels, else 1.
#include <glm/vec2.hpp>
#include <vector>

namespace cutaway::pipeline {

/// One dispatch of a pass: along each axis either paired pixels (invocation i covers
/// i + (i / step) * step and that plus the step, counted from 0) or single ones (origin + i).
struct JumpFloodRegion {
    bool paired_x = false, paired_y = false;
    glm::ivec2 origin{0};       ///< added to the invocation's first pixel (0 along a paired axis)
    glm::ivec2 invocations{0};  ///< > 0 along both axes
};

/// The regions of a pass of `step` (a power of two) over width x height pixels: every pixel in
/// exactly one block of exactly one region (jump_flood_split_test).
std::vector<JumpFloodRegion> jump_flood_regions(int width, int height, int step);

}  // namespace cutaway::pipeline
