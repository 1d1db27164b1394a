#version 450 core
// One level of the min/max pyramid of the cut depth (hierarchical-Z for culling, SPEC.md
// section 6), kept in one buffer of (min, max) pairs, level after level, rows bottom to top.
// Texel t of a level covers texels 2t and 2t+1 of the level below along each axis; the last
// texel also takes the odd leftover, so every level covers the whole image.
// Variant FIRST_LEVEL: the level below is the cut surface itself (A = depth, 0 = nothing cut).
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 13) buffer CutPyramid { vec2 pyramid[]; };

uniform ivec2 level_size;
uniform int level_offset;
#ifdef FIRST_LEVEL
uniform sampler2D cut_surface;
#else
uniform ivec2 below_size;
uniform int below_offset;
#endif

vec2 below_range(ivec2 texel) {
#ifdef FIRST_LEVEL
    return vec2(texelFetch(cut_surface, texel, 0).a);
#else
    return pyramid[below_offset + texel.y * below_size.x + texel.x];
#endif
}

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, level_size))) return;
#ifdef FIRST_LEVEL
    ivec2 src = textureSize(cut_surface, 0);
#else
    ivec2 src = below_size;
#endif
    ivec2 first = min(2 * t, src - 1);
    ivec2 last = min(mix(2 * t + 1, src - 1, equal(t, level_size - 1)), src - 1);
    vec2 range = vec2(3.0e38, -3.0e38);
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) {
            vec2 r = below_range(ivec2(x, y));
            range = vec2(min(range.x, r.x), max(range.y, r.y));
        }
    pyramid[level_offset + t.y * level_size.x + t.x] = range;
}
