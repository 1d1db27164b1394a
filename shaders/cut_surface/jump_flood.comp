#version 450 core
// One jump flooding pass on the GPU (cone_field/jump_flooding.h, the CPU reference): every pixel
// holds a seed (owner) or none and keeps, among its own and the 8 owners (+-k, 0, +-k) away, the
// one whose cone t(q) - slope |q - p| is highest here; on a tie the one it holds, then the first
// in the reference's row-major tap order (its rows run top to bottom, ours bottom to top, so its
// tap (tx, ty) is our offset (tx, -ty)). Texel: x = owner's x | y << 16 (no_owner: none),
// y = the owner's stored depth t as float bits, so one fetch per tap.
// Variant INIT: the first texel image from the seed image (cone_seed.glsl).
layout(local_size_x = 8, local_size_y = 8) in;

layout(rg32ui, binding = 0) uniform writeonly uimage2D owners_out;

const uint no_owner = 0xffffffffu;

#ifdef INIT
#include "cut_surface/cone_seed.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(owners_out)))) return;
    float seed = seed_at(p);
    imageStore(owners_out, p, seed > 0.0 ? uvec4(uint(p.x) | uint(p.y) << 16, floatBitsToUint(seed), 0u, 0u) : uvec4(no_owner, 0u, 0u, 0u));
}
#else
uniform usampler2D owners_in;
uniform int step_size;  // pixels
uniform float slope;    // stored depth units per pixel

#include "cut_surface/cone_height.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = textureSize(owners_in, 0);
    if (any(greaterThanEqual(p, size))) return;
    uvec2 best = texelFetch(owners_in, p, 0).xy;
    float best_height = best.x == no_owner ? 0.0 : owner_height(best, p, slope);
    for (int ty = -1; ty <= 1; ++ty)
        for (int tx = -1; tx <= 1; ++tx) {
            ivec2 n = p + ivec2(tx, -ty) * step_size;
            if (any(lessThan(n, ivec2(0))) || any(greaterThanEqual(n, size))) continue;
            uvec2 owner = texelFetch(owners_in, n, 0).xy;
            if (owner.x == no_owner || owner.x == best.x) continue;
            float candidate = owner_height(owner, p, slope);
            if (best.x == no_owner || candidate > best_height) {
                best = owner;
                best_height = candidate;
            }
        }
    imageStore(owners_out, p, uvec4(best, 0u, 0u));
}
#endif
