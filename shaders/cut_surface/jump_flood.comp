#version 450 core
// One jump flooding pass on the GPU (cone_field/jump_flooding.h, the CPU reference): every pixel
// holds a seed (owner) or none and keeps, among its own and the 8 owners (+-k, 0, +-k) away, the
// one whose cone t(q) - slope |q - p| is highest here; on a tie the one it holds, then the first
// in the reference's row-major tap order (its rows run top to bottom, ours bottom to top, so its
// tap (tx, ty) is our offset (tx, -ty)). Texel: x = 1 + (owner's x | y << 16), 0 for none, so
// that a tap outside the image, which imageLoad reads as 0, holds no owner (no bounds test);
// y = the owner's stored depth t as float bits, so one load per tap. The taps are selects, not
// branches (SIMD lanes on a CPU rasteriser stay together).
// Variant INIT: the first texel image from the seed image (cone_seed.glsl).
layout(local_size_x = GROUP_X, local_size_y = GROUP_Y) in;

layout(rg32ui, binding = 0) uniform writeonly uimage2D owners_out;

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
uniform int step_size;  // pixels
uniform float slope;    // stored depth units per pixel

#include "cut_surface/cone_height.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(owners_in)))) return;
    uvec2 best = imageLoad(owners_in, p).xy;
    float best_height = owner_height(best, p, slope);
    // The reference's taps in its order, its own (0, 0) left out (it is already best).
    const ivec2 taps[8] = ivec2[](ivec2(-1, 1), ivec2(0, 1), ivec2(1, 1), ivec2(-1, 0), ivec2(1, 0), ivec2(-1, -1),
                                  ivec2(0, -1), ivec2(1, -1));
    for (int i = 0; i < 8; ++i) {
        uvec2 owner = imageLoad(owners_in, p + taps[i] * step_size).xy;
        float candidate = owner_height(owner, p, slope);
        bool take = owner.x != 0u && owner.x != best.x && (best.x == 0u || candidate > best_height);
        best = take ? owner : best;
        best_height = take ? candidate : best_height;
    }
    imageStore(owners_out, p, uvec4(best, 0u, 0u));
}
#endif
