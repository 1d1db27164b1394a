// Names and numbers C++ and GLSL share, defined once: shaders include it through the shader
// library ("common/shared_constants.h"), C++ with shaders/ on its include path. No other #include
// may appear here (the shader library would try to inline it).
#ifndef CUTAWAY_SHARED_CONSTANTS_H
#define CUTAWAY_SHARED_CONSTANTS_H

#ifdef __cplusplus
namespace cutaway::shared {
using uint = unsigned int;
#define CUTAWAY_SHARED_CONST inline constexpr
#else
#define CUTAWAY_SHARED_CONST const
#endif

// Flags stages 2 and 3 keep per pixel (the scene id target's second channel,
// src/cutaway/frame_targets.h); the image metrics read them back (src/metrics/image_metrics.h).
CUTAWAY_SHARED_CONST uint flag_primary = 1u;
CUTAWAY_SHARED_CONST uint flag_cut_fill = 2u;    // a cell's inside seen through the cut
CUTAWAY_SHARED_CONST uint flag_border = 4u;      // border line where a face meets the cut
CUTAWAY_SHARED_CONST uint flag_edge = 8u;        // cell edge line
CUTAWAY_SHARED_CONST uint flag_shell_cut = 16u;  // border line on a shell face
// A well tube (stage 3, primary/well.frag): its pixel shows no cell (id 0), and the flags' bits
// from well_index_shift up hold the well's index in the renderer's well set. The distributed
// compositor carries flags as floats, exact below 2^24: at most max_drawn_wells wells.
CUTAWAY_SHARED_CONST uint flag_well = 32u;
CUTAWAY_SHARED_CONST uint well_index_shift = 8u;
CUTAWAY_SHARED_CONST uint max_drawn_wells = 65535u;

#undef CUTAWAY_SHARED_CONST
#ifdef __cplusplus
}  // namespace cutaway::shared
#endif

#endif
