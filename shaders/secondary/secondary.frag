#version 450 core
// Stage 2: secondary cells clipped by the cut surface. Kept fragments seen from inside their
// cell (the cell's inside exposed by the cut) take the cut surface's normal so cells look solid
// (common/secondary_shading.glsl).
// Variants: BORDER_RAYCAST (the paper's border test, run per visible pixel by
// secondary/raycast_borders.comp from the face plane written here) or BORDER_THRESHOLD (naive,
// here), HIDE_INTERNAL_LINES, NEAREST_FACE_TESTED (second of two passes: only the face that
// secondary/nearest_face.frag left at the pixel is shaded; the depth test, GL_EQUAL, runs first),
// DEFERRED (the cut test only: the nearest kept fragment leaves its cell, face info, edge line,
// face normal and linear depth, and secondary/deferred_shading.comp shades each pixel once),
// CUT_CAMERA_IS_VIEW (common/fragment_cut.glsl).
#include "common/shared_constants.h"
#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/cut_lookup.glsl"
#include "common/fragment_cut.glsl"
#include "common/frame_outputs.glsl"
#include "common/secondary_shading.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform float line_width;       // pixels

#ifdef NEAREST_FACE_TESTED
layout(early_fragment_tests) in;
layout(binding = tex_nearest_face) uniform usampler2D nearest_face;  // 1 + face index, 0 = none
#endif
#ifdef DEFERRED
#include "common/deferred_face.glsl"
#endif

void main() {
#ifdef NEAREST_FACE_TESTED
    // The nearest face passed the cut test in the first pass; a tied face drawn later did not win.
    if (texelFetch(nearest_face, ivec2(gl_FragCoord.xy), 0).r != v_in.face_index) discard;
    CutSample here = fragment_cut(v_in.cut_clip, v_in.cut_eye_depth);
#else
    CutSample here = fragment_cut(v_in.cut_clip, v_in.cut_eye_depth);
    if (clipped(here, v_in.world_position, ivec2(gl_FragCoord.xy))) discard;
#endif
#ifdef CUT_CAMERA_IS_VIEW
    float linear_depth = here.fragment_depth;  // the cut camera is the model camera
#else
    float linear_depth = -(model_view * vec4(v_in.world_position, 1.0)).z;
#endif
    float edge_opacity = face_edge_opacity(v_in.edge_distance, line_width);
#ifdef DEFERRED
    // Written to SceneTargets::deferred_framebuffer: the id and face plane targets only.
    out_id = uvec2(v_in.compact_cell + 1u, pack_deferred_face(v_in.face_info, edge_opacity));
    out_face_plane = pack_normal_and(v_in.face_normal, linear_depth);  // and the linear depth
#else
    SecondaryShade s = shade_secondary(here, v_in.world_position, ivec2(gl_FragCoord.xy), v_in.compact_cell,
                                       v_in.face_info, v_in.face_normal, edge_opacity, edge_opacity > 0.5);
    write_frame_at_depth(s.colour, s.normal, linear_depth, v_in.compact_cell, s.flags);
#ifdef BORDER_RAYCAST
    // The ray-cast test runs once per visible pixel afterwards (secondary/raycast_borders.comp).
    out_face_plane = pack_normal_and(v_in.face_normal, 1.0 + float(v_in.face_info & 3u));  // and 1 + face class
#endif
#endif
}
