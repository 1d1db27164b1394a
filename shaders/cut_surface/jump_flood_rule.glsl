// The jump flooding rule at one pixel (jump_flood.comp; cone_field/jump_flooding.h, the CPU
// reference): among the pixel's own owner and the 8 tapped ones, in the reference's tap order,
// keep the one whose cone is highest here; on a tie the one it holds, then the first tap.
// Texels: x = 1 + (qx | qy << 16), 0 = no owner; y = the owner's stored depth t as float bits.

// Height at pixel p of an owner texel's cone (meaningless for no owner): t(q) - slope |q - p|,
// the distance computed as the CPU reference does (sqrt(dx^2 + dy^2)).
float owner_height(uvec2 owner, ivec2 p, float slope) {
    uint q = owner.x - 1u;
    vec2 d = vec2(ivec2(int(q & 0xffffu), int(q >> 16)) - p);
    return uintBitsToFloat(owner.y) - slope * sqrt(d.x * d.x + d.y * d.y);
}

// The reference's taps in its order, its own (0, 0) left out (it is already best). Its rows run
// top to bottom, ours bottom to top, so its tap (tx, ty) is our offset (tx, -ty).
const ivec2 flood_taps[8] = ivec2[](ivec2(-1, 1), ivec2(0, 1), ivec2(1, 1), ivec2(-1, 0), ivec2(1, 0), ivec2(-1, -1),
                                    ivec2(0, -1), ivec2(1, -1));

struct FloodBest {
    uvec2 owner;
    float height;
};

FloodBest flood_start(uvec2 own, ivec2 p, float slope) { return FloodBest(own, owner_height(own, p, slope)); }

// Selects, not branches: SIMD lanes on a CPU rasteriser stay together.
FloodBest flood_take(FloodBest best, uvec2 owner, ivec2 p, float slope) {
    float candidate = owner_height(owner, p, slope);
    bool take = owner.x != 0u && owner.x != best.owner.x && (best.owner.x == 0u || candidate > best.height);
    return FloodBest(take ? owner : best.owner, take ? candidate : best.height);
}
