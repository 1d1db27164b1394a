#version 450 core
// Stage 2, first of two passes (the visible path): the cut test and depth only, leaving at each
// pixel the nearest kept fragment's face (common/face_varyings.glsl face_index; the first drawn
// wins a depth tie, as in one GL_LESS pass). The shaded pass (secondary.frag, NEAREST_FACE_TESTED)
// then runs its lighting and G-buffer writes once per pixel instead of once per fragment drawn:
// at petra's default camera, 21M fragments cover 2M pixels.
#include "common/cut_lookup.glsl"
#include "common/fragment_cut.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

layout(location = 0) out uint out_face;

void main() {
    CutSample here = fragment_cut(v_in.cut_clip, v_in.cut_eye_depth);
    if (clipped(here, v_in.world_position, ivec2(gl_FragCoord.xy))) discard;
    out_face = v_in.face_index;
}
