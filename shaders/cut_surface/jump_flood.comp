#version 450 core
// One jump flooding pass on the GPU (cone_field/jump_flooding.h, the CPU reference; the rule in
// jump_flood_rule.glsl): every pixel keeps, among its own owner and the 8 owners (+-k, 0, +-k)
// away, the one whose cone is highest there.
// Owners image: one RGBA32UI texel per 2 horizontally adjacent pixels (xy: pixel 2i, zw: pixel
// 2i + 1; with an odd width the last texel's zw stays "no owner"). Per pixel: x = 1 + (owner's
// x | y << 16), 0 for none, so that a tap outside the image, which imageLoad reads as 0, holds no
// owner (no bounds test); y = the owner's stored depth t as float bits, so one load per tap.
// Each invocation floods one texel's 2 pixels in BLOCK_Y rows a step apart (1 or 2,
// jump_flood_split.h), from the (BLOCK_Y + 2) x 3 texels that hold all their taps: a step of 2k
// puts a pixel's taps k texels away in the same half, a step of 1 in the texels beside.
// On llvmpipe an image store costs several times a load, whatever its size: 2 pixels per store
// made a pass faster than one pixel per store (jfa2, gpu_jump_flooding.cpp).
// Variant INIT: the first owners image from the seed image (cone_seed.glsl). Variant CUT_OUT:
// the last pass, storing each pixel's cut instead of its owner: the owner cone's height, clamped
// to [0, 1] (0: nothing cut; no owner's height is negative, flood_take), as the cut depth image
// holds it (rows bottom to top).
layout(local_size_x = GROUP_X, local_size_y = GROUP_Y) in;

uniform int width;  // the image's pixels per row (the owners image has (width + 1) / 2 texels)

#ifdef CUT_OUT
layout(r32f, binding = 0) uniform writeonly imageBuffer cut_out;  // gl/float_image_buffer.h
#else
layout(rgba32ui, binding = 0) uniform writeonly uimage2D owners_out;
#endif

#ifdef INIT
#include "cut_surface/cone_seed.glsl"

// A pixel's owner for the seed `seed` at pixel p (0: none).
uvec2 seed_owner(ivec2 p, float seed) { return seed > 0.0 ? uvec2(1u + (uint(p.x) | uint(p.y) << 16), floatBitsToUint(seed)) : uvec2(0u); }

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(owners_out)))) return;
    ivec2 left = ivec2(2 * texel.x, texel.y), right = left + ivec2(1, 0);
    uvec2 right_owner = right.x < width ? seed_owner(right, seed_at(right)) : uvec2(0u);
    imageStore(owners_out, texel, uvec4(seed_owner(left, seed_at(left)), right_owner));
}
#else
layout(rgba32ui, binding = 1) uniform readonly uimage2D owners_in;
uniform int step_log2;  // the step is 1 << step_log2 pixels
uniform float slope;    // stored depth units per pixel
uniform ivec2 origin;       // the first texel of the region this dispatch covers
uniform ivec2 invocations;  // the region's invocations (the last work groups' others store nothing)

#include "cut_surface/jump_flood_rule.glsl"

// Invocation -> the first of its BLOCK_Y rows, which lie one step apart: with a block of 2,
// invocation i covers row i + (i / step) * step and that plus the step.
int block_start(int id, int block) { return id + (block - 1) * ((id >> step_log2) << step_log2); }

// The owner at tap tx (-1, 0, 1) of pixel `half_index` (0: left, 1: right) of the middle texel of
// `row`, which holds the texels -m, 0 and +m away, m = max(1, step / 2).
FloodOwner tap_owner(FloodOwner row[3][2], int half_index, int tx) {
    int pixel = half_index + tx;  // for a step of 1: the pixel, counted from the middle texel's left one
    return step_log2 == 0 ? row[(pixel >> 1) + 1][pixel & 1] : row[tx + 1][half_index];
}

void main() {
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);
    int step_size = 1 << step_log2, texel_step = max(1, step_size >> 1);
    ivec2 start = origin + ivec2(id.x, block_start(id.y, BLOCK_Y));
    // The texels holding the block's pixels and their taps, each pixel's owner decoded once.
    FloodOwner owners[BLOCK_Y + 2][3][2];
    for (int j = 0; j < BLOCK_Y + 2; ++j)
        for (int i = 0; i < 3; ++i) {
            uvec4 texel = imageLoad(owners_in, start + ivec2((i - 1) * texel_step, (j - 1) * step_size));
            owners[j][i][0] = flood_owner(texel.xy);
            owners[j][i][1] = flood_owner(texel.zw);
        }
    bool stores = all(lessThan(id, invocations));
    for (int by = 0; by < BLOCK_Y; ++by) {
        FloodBest best[2];
        for (int h = 0; h < 2; ++h) {
            vec2 p = vec2(2 * start.x + h, start.y + by * step_size);
            best[h] = flood_start(owners[by + 1][1][h], p, slope);
            for (int t = 0; t < 8; ++t)
                best[h] = flood_take(best[h], tap_owner(owners[by + 1 + flood_taps[t].y], h, flood_taps[t].x), p, slope);
        }
        ivec2 texel = ivec2(start.x, start.y + by * step_size);
        bool right_inside = 2 * texel.x + 1 < width;
#ifdef CUT_OUT
        int left = texel.y * width + 2 * texel.x;
        if (stores) imageStore(cut_out, left, vec4(clamp(best[0].height, 0.0, 1.0)));
        if (stores && right_inside) imageStore(cut_out, left + 1, vec4(clamp(best[1].height, 0.0, 1.0)));
#else
        if (stores) imageStore(owners_out, texel, uvec4(best[0].owner, right_inside ? best[1].owner : uvec2(0u)));
#endif
    }
}
#endif
