// The jump flooding rule at one pixel (jump_flood.comp; cone_field/jump_flooding.h, the CPU
// reference): among the pixel's own owner and the 8 tapped ones, in the reference's tap order,
// keep the one whose cone is highest here; on a tie the one it holds, then the first tap.
// A pixel's owner (its half of an owners texel, jump_flood.comp): x = 1 + (qx | qy << 16), 0 = no
// owner; y = the owner's stored depth t as float bits.

// A pixel's owner decoded once (a pass evaluates each loaded owner at up to 4 pixels):
// the owner's pixel and stored depth t as floats (integers below 2^24: exact).
struct FloodOwner {
    uvec2 texel;
    vec2 at;
    float depth;
};

FloodOwner flood_owner(uvec2 owner) {
    uint q = owner.x - 1u;
    return FloodOwner(owner, vec2(float(q & 0xffffu), float(q >> 16)), uintBitsToFloat(owner.y));
}

// Height at pixel p of an owner's cone (for no owner, see flood_take): t(q) - slope |q - p|, the
// distance computed as the CPU reference does (sqrt(dx^2 + dy^2)).
float owner_height(FloodOwner owner, vec2 p, float slope) {
    vec2 d = owner.at - p;
    return owner.depth - slope * sqrt(d.x * d.x + d.y * d.y);
}

// The reference's taps in its order, its own (0, 0) left out (it is already best). Its rows run
// top to bottom, ours bottom to top, so its tap (tx, ty) is our offset (tx, -ty).
const ivec2 flood_taps[8] = ivec2[](ivec2(-1, 1), ivec2(0, 1), ivec2(1, 1), ivec2(-1, 0), ivec2(1, 0), ivec2(-1, -1),
                                    ivec2(0, -1), ivec2(1, -1));

struct FloodBest {
    uvec2 owner;
    float height;
};

FloodBest flood_start(FloodOwner own, vec2 p, float slope) { return FloodBest(own.texel, owner_height(own, p, slope)); }

// No owner (x = 0, also what a tap outside the image reads) decodes as a seed at (65535, 65535) of
// depth 0, whose height is below every owner's anywhere in an image of at most 32768 pixels a side
// (slope > 0: t - slope |q - p| >= -slope |q - p| > -slope |(65535, 65535) - p|), so "higher"
// alone keeps the reference's rule: an owner replaces no owner, no owner never replaces one, and
// the same owner, or a different one of equal height, never replaces the one held. One compare
// per tap, and selects, not branches: SIMD lanes on a CPU rasteriser stay together.
FloodBest flood_take(FloodBest best, FloodOwner owner, vec2 p, float slope) {
    float candidate = owner_height(owner, p, slope);
    bool take = candidate > best.height;
    return FloodBest(take ? owner.texel : best.owner, take ? candidate : best.height);
}
