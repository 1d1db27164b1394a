#version 450 core
// Stage 1, frustum union: one point per primary cell. The cell's 8 corners go to the cut
// camera's eye space; the box is kept in perspective-divided coordinates (u = x/s, v = y/s,
// s = depth along the view axis), where view rays are lines of constant (u, v), so the box's
// (u, v) range covers every pixel the cell covers.
#include "common/grid.glsl"

layout(std430, binding = 5) readonly buffer PrimaryCells { uint primary_cells[]; };

uniform mat4 cut_view;
uniform float near_plane;

out CellBox {
    vec4 uv_box;       // u0, v0, u1, v1
    float far_depth;   // largest corner depth s
} box;

void main() {
    uint cell = primary_cells[gl_VertexID];
    vec2 lo = vec2(1e30);
    vec2 hi = vec2(-1e30);
    float far_depth = near_plane;
    for (uint c = 0u; c < 8u; ++c) {
        vec4 eye = cut_view * vec4(corner_position(cell, c), 1.0);
        float s = max(-eye.z, near_plane);  // corners behind the near plane: widest footprint
        vec2 uv = eye.xy / s;
        lo = min(lo, uv);
        hi = max(hi, uv);
        far_depth = max(far_depth, -eye.z);
    }
    box.uv_box = vec4(lo, hi);
    box.far_depth = far_depth;
    gl_Position = vec4(0.0);
}
