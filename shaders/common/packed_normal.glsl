// A unit normal and a float in two 32-bit words, as the scene's RG32UI targets hold them
// (src/cutaway/frame_targets.h: normal_depth, face_plane): the normal in the octahedral map
// (Cigolle et al., "A Survey of Efficient Representations for Independent Unit Vectors", JCGT
// 2014) quantised to two 16-bit snorms (packSnorm2x16: at most about 0.0001 radian off, far below
// what a lit 8-bit colour shows), the float's bits unchanged. 8 bytes per pixel where RGBA32F took 16.

#ifndef CUTAWAY_PACKED_NORMAL_GLSL
#define CUTAWAY_PACKED_NORMAL_GLSL

vec2 octahedral_sign(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

uint pack_unit_normal(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 folded = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * octahedral_sign(n.xy);
    return packSnorm2x16(folded);
}

vec3 unpack_unit_normal(uint bits) {
    vec2 e = unpackSnorm2x16(bits);
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * octahedral_sign(n.xy);
    return normalize(n);
}

uvec2 pack_normal_and(vec3 unit_normal, float value) { return uvec2(pack_unit_normal(unit_normal), floatBitsToUint(value)); }
vec3 packed_normal(uvec2 words) { return unpack_unit_normal(words.x); }
float packed_value(uvec2 words) { return uintBitsToFloat(words.y); }
#endif
