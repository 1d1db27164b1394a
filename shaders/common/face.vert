#version 450 core
// One face record -> one indexed quad (src/cutaway/quad_draw.h: 4 vertices, gl_VertexID / 4 =
// face, gl_VertexID % 4 = corner, triangles (0, 1, 2), (0, 2, 3)). Each vertex rebuilds
// the face's 4 corners so it can give the window-space distance to the quad's 4 edges
// (single-pass wireframe, Baerentzen et al. 2006) without a geometry shader.
// Variants: CULL_FRONT_INTERIOR (secondaries: an interior face seen from outside its cell always
// coincides with its neighbour's copy, which is the one kept), CULL_BACK (primaries, shell),
// CULL_FRONT (the rear shell: only faces seen from inside their cell); PLAIN_FRAME (no cut read).
#include "common/grid.glsl"
#include "common/face_frame.glsl"

layout(std430, binding = 3) readonly buffer Faces { uint faces[]; };

uniform mat4 view_projection;
uniform vec3 eye_position;  // render space
uniform vec2 viewport_size; // pixels
uniform mat4 cut_view;             // the cut camera (stage 2 clips against its image)
uniform mat4 cut_view_projection;

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
    FaceFrame f = face_frame(cell, side, eye_position);
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
#ifdef CULL_FRONT
    culled = culled || !back_facing;
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
#endif
}
