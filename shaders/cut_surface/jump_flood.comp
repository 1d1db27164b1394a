#version 450 core
// One jump flooding pass on the GPU (cone_field/jump_flooding.h, the CPU reference; the rule in
// jump_flood_rule.glsl): every pixel keeps, among its own owner and the 8 owners (+-k, 0, +-k)
// away, the one whose cone is highest there. Each invocation floods a BLOCK_X x BLOCK_Y block of
// pixels one step apart (1 or 2 along each axis, jump_flood_split.h), loading the block's
// (BLOCK_X + 2) x (BLOCK_Y + 2) owners once. Texel: x = 1 + (owner's x | y << 16), 0 for none, so
// that a tap outside the image, which imageLoad reads as 0, holds no owner (no bounds test);
// y = the owner's stored depth t as float bits, so one load per tap.
// Variant INIT: the first owners image from the seed image (cone_seed.glsl). Variant CUT_OUT:
// the last pass, storing each pixel's cut instead of its owner: the owner cone's height, clamped
// to [0, 1] (0: nothing cut), as the cut depth image holds it (rows bottom to top).
layout(local_size_x = GROUP_X, local_size_y = GROUP_Y) in;

#ifdef CUT_OUT
layout(r32f, binding = 0) uniform writeonly imageBuffer cut_out;  // gl/float_image_buffer.h
#else
layout(rg32ui, binding = 0) uniform writeonly uimage2D owners_out;
#endif

#ifdef INIT
#include "cut_surface/cone_seed.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(owners_out)))) return;
    float seed = seed_at(p);
    imageStore(owners_out, p, seed > 0.0 ? uvec4(1u + (uint(p.x) | uint(p.y) << 16), floatBitsToUint(seed), 0u, 0u) : uvec4(0u));
}
#else
layout(rg32ui, binding = 1) uniform readonly uimage2D owners_in;
uniform int step_log2;  // the step is 1 << step_log2 pixels
uniform float slope;    // stored depth units per pixel
uniform ivec2 origin;       // the first pixel of the region this dispatch covers
uniform ivec2 invocations;  // the region's invocations (the last work groups' others store nothing)

#include "cut_surface/jump_flood_rule.glsl"

// Invocation -> the first of its BLOCK_X x BLOCK_Y pixels, which lie one step apart: along an axis
// with a block of 2, invocation i covers i + (i / step) * step and that plus the step.
int block_start(int id, int block) { return id + (block - 1) * ((id >> step_log2) << step_log2); }

void main() {
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);
    int step_size = 1 << step_log2;
    ivec2 start = origin + ivec2(block_start(id.x, BLOCK_X), block_start(id.y, BLOCK_Y));
    // The owners of the block's pixels and their taps: (BLOCK + 2)^2 loads, shared between the pixels.
    uvec2 texels[BLOCK_Y + 2][BLOCK_X + 2];
    for (int j = 0; j < BLOCK_Y + 2; ++j)
        for (int i = 0; i < BLOCK_X + 2; ++i) texels[j][i] = imageLoad(owners_in, start + ivec2(i - 1, j - 1) * step_size).xy;
    bool stores = all(lessThan(id, invocations));
    for (int by = 0; by < BLOCK_Y; ++by)
        for (int bx = 0; bx < BLOCK_X; ++bx) {
            ivec2 p = start + ivec2(bx, by) * step_size;
            FloodBest best = flood_start(texels[by + 1][bx + 1], p, slope);
            for (int t = 0; t < 8; ++t) {
                ivec2 tap = ivec2(bx + 1, by + 1) + flood_taps[t];
                best = flood_take(best, texels[tap.y][tap.x], p, slope);
            }
#ifdef CUT_OUT
            if (stores) imageStore(cut_out, p.y * imageSize(owners_in).x + p.x, vec4(best.owner.x == 0u ? 0.0 : clamp(best.height, 0.0, 1.0)));
#else
            if (stores) imageStore(owners_out, p, uvec4(best.owner, 0u, 0u));
#endif
        }
}
#endif
