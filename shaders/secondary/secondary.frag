#version 450 core
// Stage 2: secondary cells clipped by the cut surface. Kept fragments seen from inside their
// cell (the cell's inside exposed by the cut) take the cut surface's normal so cells look solid.
// Variants: BORDER_RAYCAST (the paper's border test) or BORDER_THRESHOLD (naive), HIDE_INTERNAL_LINES.
#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/cut_lookup.glsl"
#include "common/frame_outputs.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform float line_width;       // pixels
uniform float border_width;     // w, pixels
uniform vec3 edge_colour;
uniform vec3 border_colour;
uniform vec3 shell_cut_colour;
uniform mat4 inverse_view_projection;  // model camera
uniform vec2 viewport_size;
uniform float focal_px;         // model camera focal length, pixels

// Point where the model camera's ray through window position `window` meets the plane.
vec3 ray_plane_hit(vec2 window, vec3 plane_point, vec3 plane_normal, out bool hit) {
    vec2 ndc = window / viewport_size * 2.0 - 1.0;
    vec4 near_point = inverse_view_projection * vec4(ndc, -1.0, 1.0);
    vec4 far_point = inverse_view_projection * vec4(ndc, 1.0, 1.0);
    vec3 origin = near_point.xyz / near_point.w;
    vec3 direction = far_point.xyz / far_point.w - origin;
    float denominator = dot(direction, plane_normal);
    hit = abs(denominator) > 1e-12;
    float t = hit ? dot(plane_point - origin, plane_normal) / denominator : 0.0;
    return origin + t * direction;
}

bool is_border(CutSample here) {
#ifdef BORDER_RAYCAST
    // The paper's test: the face's plane seen through the 4 pixels at distance w; if the cut
    // would clip it at any of them, this pixel lies within w of the border.
    const vec2 offsets[4] = vec2[](vec2(1.0, 0.0), vec2(-1.0, 0.0), vec2(0.0, 1.0), vec2(0.0, -1.0));
    for (int n = 0; n < 4; ++n) {
        bool hit;
        vec3 point = ray_plane_hit(gl_FragCoord.xy + border_width * offsets[n], v_in.world_position, v_in.face_normal, hit);
        if (!hit) continue;
        CutSample there = cut_at(point);
        if (there.fragment_depth < there.cut_depth) return true;
    }
    return false;
#else
    // Naive: depth within epsilon of the cut, epsilon = the depth w pixels span at this distance.
    float epsilon = border_width * here.fragment_depth / focal_px;
    return here.cut_depth > 0.0 && here.fragment_depth - here.cut_depth < epsilon;
#endif
}

void main() {
    CutSample here = cut_at(v_in.world_position);
    if (here.fragment_depth < here.cut_depth) discard;
    bool inside_view = (v_in.face_info & 4u) != 0u;
    uint face_class = v_in.face_info & 3u;
    vec3 normal = inside_view ? cut_normal_at(here.texel) : v_in.face_normal;
    if (inside_view && here.cut_depth == 0.0) normal = -v_in.face_normal;
    vec3 colour = lit(cell_colour(v_in.compact_cell), normal, v_in.world_position);
    uint flags = inside_view ? flag_cut_fill : 0u;

    float edge = min(min(v_in.edge_distance.x, v_in.edge_distance.y), min(v_in.edge_distance.z, v_in.edge_distance.w));
    float edge_opacity = line_opacity(edge, line_width);
#ifdef HIDE_INTERNAL_LINES
    if (inside_view) edge_opacity = 0.0;
#endif
    colour = mix(colour, edge_colour, edge_opacity);
    if (edge_opacity > 0.5) flags |= flag_edge;

    if (is_border(here)) {
        bool shell = face_class == face_class_shell;
        colour = shell ? shell_cut_colour : border_colour;
        flags |= shell ? (flag_border | flag_shell_cut) : flag_border;
    }
    write_frame(colour, normal, v_in.world_position, v_in.compact_cell, flags);
}
