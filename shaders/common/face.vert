#version 450 core
// One face record -> one indexed quad (src/cutaway/quad_draw.h: 4 vertices, gl_VertexID / 4 =
// face, gl_VertexID % 4 = corner, triangles (0, 1, 2), (0, 2, 3)). Each vertex rebuilds
// the face's 4 corners so it can give the window-space distance to the quad's 4 edges
// (single-pass wireframe, Baerentzen et al. 2006) without a geometry shader.
// Variants: CULL_FRONT_INTERIOR (secondaries: an interior face seen from outside its cell always
// coincides with its neighbour's copy, which is the one kept), CULL_BACK (primaries),
// SHELL_BACKS (back-facing shell faces only: the far walls of hidden primaries where they are the
// model's outer surface, primary/primary.frag HIDDEN_WALLS);
// PLAIN_FRAME (no cut read);
// STORED_CORNERS (the face's corners read from src/cutaway/exposed_surface.h's buffer, 4 per
// face in drawing order) with CULL_HIDDEN_BACK (a face both of whose triangles face away, which
// its own cell hides, is dropped: what visibility/cull_cells.comp keeps behind the cut).
#include "common/shared_constants.h"
#include "common/grid.glsl"
#include "common/cameras.glsl"
#include "common/face_frame.glsl"

layout(std430, binding = ssbo_faces) readonly buffer Faces { uint faces[]; };
#ifdef STORED_CORNERS
layout(binding = tex_stored_corners) uniform samplerBuffer stored_corner_texels;  // RGB32F, 4 per face
#endif


// The same face rasterises to the same depths in every program that draws it: stage 2's shaded
// pass tests GL_EQUAL against the depths secondary/nearest_face.frag left.
invariant gl_Position;

out FaceVaryings {
#include "common/face_varyings.glsl"
} v_out;

vec2 to_window(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * viewport_size; }

float distance_to_line(vec2 p, vec2 a, vec2 b) {
    vec2 ab = b - a;
    float length_ab = length(ab);
    return length_ab > 0.0 ? abs(ab.x * (p.y - a.y) - ab.y * (p.x - a.x)) / length_ab : length(p - a);
}

void main() {
    uint record = faces[gl_VertexID / 4];
    uint cell = face_record_cell(record);
    uint side = face_record_side(record);
    uint face_class = face_record_class(record);
#ifdef STORED_CORNERS
    vec3 stored[4];
    for (int k = 0; k < 4; ++k) stored[k] = texelFetch(stored_corner_texels, 4 * (gl_VertexID / 4) + k).xyz;
    FaceFrame f = face_frame_of_quad(stored, cell, eye_position);
#else
    FaceFrame f = face_frame(cell, side, eye_position);
#endif
    vec3 q[4] = f.q;
    vec3 normal = f.normal;
    bool back_facing = f.back_facing;
    bool culled = f.collapsed;
#ifdef CULL_FRONT_INTERIOR
    culled = culled || (!back_facing && face_class == face_class_interior);
#endif
#ifdef CULL_BACK
    culled = culled || back_facing;
#endif
#ifdef SHELL_BACKS
    culled = culled || !back_facing || face_class != face_class_shell;
#endif
#ifdef CULL_HIDDEN_BACK
    culled = culled || !f.any_triangle_front_facing;
#endif
    if (culled) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // all 4 vertices outside the clip volume
        v_out.world_position = vec3(0.0);
        v_out.face_normal = vec3(0.0, 0.0, 1.0);
        v_out.compact_cell = 0u;
        v_out.face_info = 0u;
        v_out.edge_distance = vec4(1e6);
#ifndef PLAIN_FRAME
        v_out.cut_clip = vec4(0.0, 0.0, 0.0, 1.0);
        v_out.cut_eye_depth = 0.0;
        v_out.face_index = 0u;
#endif
        return;
    }
    vec4 clip[4];
    bool in_front = true;
    for (uint k = 0u; k < 4u; ++k) {
        clip[k] = view_projection * vec4(q[k], 1.0);
        in_front = in_front && clip[k].w > 0.0;
    }
    uint me = uint(gl_VertexID) % 4u;
    vec4 distances = vec4(1e6);
    if (in_front) {
        vec2 w[4];
        for (uint k = 0u; k < 4u; ++k) w[k] = to_window(clip[k]);
        for (uint e = 0u; e < 4u; ++e) distances[e] = distance_to_line(w[me], w[e], w[(e + 1u) % 4u]);
    }
    gl_Position = clip[me];
    v_out.world_position = q[me];
    v_out.face_normal = normalize(normal);
    v_out.compact_cell = cell;
    v_out.face_info = face_class | (back_facing ? 4u : 0u);
    v_out.edge_distance = distances;
#ifndef PLAIN_FRAME
    v_out.cut_clip = cut_view_projection * vec4(q[me], 1.0);
    v_out.cut_eye_depth = -(cut_view * vec4(q[me], 1.0)).z;
    v_out.face_index = uint(gl_VertexID) / 4u + 1u;
#endif
}
