#version 450 core
// One level of the min/max pyramid of the cut depth (hierarchical-Z for culling, SPEC.md
// section 6), kept in one buffer of (min, max) pairs, level after level, rows bottom to top.
// Texel t of a level covers texels 2t and 2t+1 of the level below along each axis; the last
// texel also takes the odd leftover, so every level covers the whole image.
// Variant FIRST_LEVEL: the level below is the cut surface itself (R32F depth, 0 = nothing cut),
// read by image loads (on llvmpipe cheaper than texelFetch). Each texel takes its 2 x 2 texels
// with 4 fixed loads; only the last row and column loop over the odd leftover (a loop whose
// bounds vary across SIMD lanes runs as long as its longest lane): the pyramid at 1080p ran
// much faster so (sapphire, alternating runs).
#include "common/shared_constants.h"
layout(local_size_x = 64, local_size_y = 4) in;

layout(std430, binding = ssbo_cut_pyramid) buffer CutPyramid { vec2 pyramid[]; };

uniform ivec2 level_size;
uniform int level_offset;
#ifdef FIRST_LEVEL
layout(r32f, binding = 0) uniform readonly image2D cut_surface;
#else
uniform ivec2 below_size;
uniform int below_offset;
#endif

vec2 below_range(ivec2 texel) {
#ifdef FIRST_LEVEL
    return vec2(imageLoad(cut_surface, texel).r);
#else
    return pyramid[below_offset + texel.y * below_size.x + texel.x];
#endif
}

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, level_size))) return;
#ifdef FIRST_LEVEL
    ivec2 src = imageSize(cut_surface);
#else
    ivec2 src = below_size;
#endif
    ivec2 first = min(2 * t, src - 1);
    ivec2 second = min(2 * t + 1, src - 1);
    vec2 a = below_range(first), b = below_range(ivec2(second.x, first.y)), c = below_range(ivec2(first.x, second.y)),
         d = below_range(second);
    vec2 range = vec2(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)));
    if (any(equal(t, level_size - 1))) {  // the last row or column also takes the odd leftover
        ivec2 last = min(mix(2 * t + 1, src - 1, equal(t, level_size - 1)), src - 1);
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) {
                vec2 r = below_range(ivec2(x, y));
                range = vec2(min(range.x, r.x), max(range.y, r.y));
            }
    }
    pyramid[level_offset + t.y * level_size.x + t.x] = range;
}
