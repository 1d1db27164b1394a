// Height at pixel p of the cone of a jump-flooding owner texel (jump_flood.comp): its stored
// depth t(q) - slope |q - p|, the distance computed as the CPU reference does (sqrt(dx^2 + dy^2)).
float owner_height(uvec2 owner, ivec2 p, float slope) {
    vec2 d = vec2(ivec2(int(owner.x & 0xffffu), int(owner.x >> 16)) - p);
    return uintBitsToFloat(owner.y) - slope * sqrt(d.x * d.x + d.y * d.y);
}
