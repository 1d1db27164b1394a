#version 450 core
// Stage 2: secondary cells clipped by the cut surface. Kept fragments seen from inside their
// cell (the cell's inside exposed by the cut) take the cut surface's normal so cells look solid.
// Variants: BORDER_RAYCAST (the paper's border test, run per visible pixel by
// secondary/raycast_borders.comp from the face plane written here) or BORDER_THRESHOLD (naive,
// here), HIDE_INTERNAL_LINES, NEAREST_FACE_TESTED (second of two passes: only the face that
// secondary/nearest_face.frag left at the pixel is shaded; the depth test, GL_EQUAL, runs first).
#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/cut_lookup.glsl"
#include "common/frame_outputs.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform float line_width;       // pixels
uniform vec3 shell_cut_colour;
uniform float focal_px;         // model camera focal length, pixels
uniform float border_width;     // w, pixels

#ifdef NEAREST_FACE_TESTED
layout(early_fragment_tests) in;
layout(binding = 7) uniform usampler2D nearest_face;  // 1 + face index, 0 = none
#endif

void main() {
#ifdef NEAREST_FACE_TESTED
    // The nearest face passed the cut test in the first pass; a tied face drawn later did not win.
    if (texelFetch(nearest_face, ivec2(gl_FragCoord.xy), 0).r != v_in.face_index) discard;
    CutSample here = cut_from_clip(v_in.cut_clip, v_in.cut_eye_depth);
#else
    CutSample here = cut_from_clip(v_in.cut_clip, v_in.cut_eye_depth);
    if (clipped(here, v_in.world_position, ivec2(gl_FragCoord.xy))) discard;
#endif
    // Frozen view: no border lines on the model camera's rear shell (as on the cut's own clamp),
    // which the frozen cut may touch where the cut camera saw a primary in front of it.
    bool on_view_rear = at_view_rear_shell(v_in.world_position, ivec2(gl_FragCoord.xy));
    bool inside_view = (v_in.face_info & 4u) != 0u;
    uint face_class = v_in.face_info & 3u;
    vec3 normal = inside_view ? cut_normal_at(here.texel) : v_in.face_normal;
    if (inside_view && here.cut_depth == 0.0) normal = -v_in.face_normal;
    vec3 colour = lit(cell_colour(v_in.compact_cell), normal, v_in.world_position);
    uint flags = inside_view ? flag_cut_fill : 0u;

    float edge_opacity = face_edge_opacity(v_in.edge_distance, line_width);
    bool hide_lines = false;  // on the cut fill, with --hide-internal-lines
#ifdef HIDE_INTERNAL_LINES
    hide_lines = inside_view;
#endif
    if (hide_lines) edge_opacity = 0.0;
    colour = mix(colour, line_colour_on(colour), edge_opacity);
    if (edge_opacity > 0.5) flags |= flag_edge;

#ifdef BORDER_THRESHOLD
    // Naive: depth within epsilon of the cut, epsilon = the depth w pixels span at this distance.
    bool shell = face_class == face_class_shell;
    if (here.cut_depth > 0.0 && !cut_is_rear_shell(here.texel) && !on_view_rear && (shell || !hide_lines) &&
        here.fragment_depth - here.cut_depth < border_width * here.fragment_depth / focal_px) {
        colour = shell ? shell_cut_colour : line_colour_on(colour);
        flags |= shell ? (flag_border | flag_shell_cut) : flag_border;
    }
#endif
    write_frame(colour, normal, v_in.world_position, v_in.compact_cell, flags);
#ifdef BORDER_RAYCAST
    // The ray-cast test runs once per visible pixel afterwards (secondary/raycast_borders.comp).
    out_face_plane = vec4(v_in.face_normal, 1.0 + float(face_class));  // w: 1 + face class
#endif
}
