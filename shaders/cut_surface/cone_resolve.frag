#version 450 core
// A GPU Chamfer transform's heights image into the cut depth image (gpu_cone_transform.h): stored
// depth t clamped to [0, 1] (0: nothing cut, at or in front of the near plane). Jump flooding
// stores its cut from its last pass instead (jump_flood.comp, CUT_OUT).
uniform sampler2D heights;

void main() { gl_FragDepth = clamp(texelFetch(heights, ivec2(gl_FragCoord.xy), 0).r, 0.0, 1.0); }
