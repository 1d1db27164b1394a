// Height at pixel p of the cone of a jump-flooding owner texel (jump_flood.comp; x = 1 + (qx |
// qy << 16), 0 = none, whose height is then meaningless): its stored depth t(q) - slope |q - p|,
// the distance computed as the CPU reference does (sqrt(dx^2 + dy^2)).
float owner_height(uvec2 owner, ivec2 p, float slope) {
    uint q = owner.x - 1u;
    vec2 d = vec2(ivec2(int(q & 0xffffu), int(q >> 16)) - p);
    return uintBitsToFloat(owner.y) - slope * sqrt(d.x * d.x + d.y * d.y);
}
