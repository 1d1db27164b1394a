#pragma once
// How a GPU jump flooding pass of one step covers the image (gpu_jump_flooding.cpp,
// shaders/cut_surface/jump_flood.comp): an invocation per column (a texel of 2 adjacent pixels)
// floods 1 or 2 rows a step apart: 2 where a row has a partner a step further in the same span of
// 2 x step rows, else 1.
#include <glm/vec2.hpp>
#include <vector>

namespace cutaway::pipeline {

/// One dispatch of a pass: along y either paired rows (invocation i covers i + (i / step) * step
/// and that plus the step, counted from 0) or single ones (origin.y + i); along x invocation i
/// covers column i.
struct JumpFloodRegion {
    bool paired_y = false;
    glm::ivec2 origin{0};       ///< added to the invocation's first column and row (x: 0; y: 0 when paired)
    glm::ivec2 invocations{0};  ///< > 0 along both axes
};

/// The regions of a pass of `step` (a power of two) over columns x rows: every row of every
/// column in exactly one block of exactly one region (jump_flood_split_test).
std::vector<JumpFloodRegion> jump_flood_regions(int columns, int rows, int step);

}  // namespace cutaway::pipeline
