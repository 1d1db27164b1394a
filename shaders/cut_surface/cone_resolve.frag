#version 450 core
// A GPU cone-field transform's result into the cut depth image (gpu_cone_transform.h): stored
// depth t clamped to [0, 1] (0: nothing cut, at or in front of the near plane).
// JUMP_FLOODING: the height of each pixel's owner cone (jump_flood.comp's texels);
// otherwise (chamfer) the heights image itself.
#ifdef JUMP_FLOODING
uniform usampler2D owners;
uniform float slope;  // stored depth units per pixel
#include "cut_surface/cone_height.glsl"
#else
uniform sampler2D heights;
#endif

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef JUMP_FLOODING
    uvec2 owner = texelFetch(owners, p, 0).xy;
    float t = owner.x == 0u ? 0.0 : owner_height(owner, p, slope);
#else
    float t = texelFetch(heights, p, 0).r;
#endif
    gl_FragDepth = clamp(t, 0.0, 1.0);
}
