#version 450 core
// Stage 2, first of two passes (the visible path): the cut test and depth only, leaving at each
// pixel the nearest kept fragment's face (common/face_varyings.glsl face_index; the first drawn
// wins a depth tie, as in one GL_LESS pass). The shaded pass (secondary.frag, NEAREST_FACE_TESTED)
// then runs its lighting and G-buffer writes once per pixel instead of once per fragment drawn:
// at petra's default camera, 21M fragments cover 2M pixels.
#include "common/cut_lookup.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

#include "common/cut_of_fragment.glsl"

layout(location = 0) out uint out_face;

void main() {
#ifdef VIEW_REAR_SHELL
    vec3 world = v_in.world_position;
#else
    vec3 world = vec3(0.0);  // not read: at_view_rear_shell is false without VIEW_REAR_SHELL
#endif
    if (clipped(cut_of_fragment(), world, ivec2(gl_FragCoord.xy))) discard;
    out_face = v_in.face_index;
}
