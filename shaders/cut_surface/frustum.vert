#version 450 core
// Stage 1, frustum union: one point per primary cell. The cell's 8 corners go to the cut
// camera's eye space; the box is kept in perspective-divided coordinates (u = x/s, v = y/s,
// s = depth along the view axis), where view rays are lines of constant (u, v), so the box's
// (u, v) range covers every pixel the cell covers.
#include "common/grid.glsl"

#ifdef CLUSTERS
// One point per cluster of primaries (cut_surface/primary_clusters.h): its cells' compact indices
// are cluster_cells[first .. first + count), (first, count) = cluster_ranges[point].
layout(binding = 12) uniform usamplerBuffer cluster_ranges;
layout(binding = 13) uniform usamplerBuffer cluster_cells;
#else
layout(std430, binding = 5) readonly buffer PrimaryCells { uint primary_cells[]; };
#endif

uniform mat4 cut_view;
uniform float near_plane;

out CellBox {
    vec4 uv_box;       // u0, v0, u1, v1
    float far_depth;   // largest corner depth s
} box;

vec2 lo = vec2(1e30);
vec2 hi = vec2(-1e30);
float far_depth;

void add_cell(uint cell) {
    for (uint c = 0u; c < 8u; ++c) {
        vec4 eye = cut_view * vec4(corner_position(cell, c), 1.0);
        float s = max(-eye.z, near_plane);  // corners behind the near plane: widest footprint
        vec2 uv = eye.xy / s;
        lo = min(lo, uv);
        hi = max(hi, uv);
        far_depth = max(far_depth, -eye.z);
    }
}

void main() {
    far_depth = near_plane;
#ifdef CLUSTERS
    uvec2 range = texelFetch(cluster_ranges, gl_VertexID).rg;
    for (uint n = 0u; n < range.y; ++n) add_cell(texelFetch(cluster_cells, int(range.x + n)).r);
#else
    add_cell(primary_cells[gl_VertexID]);
#endif
    box.uv_box = vec4(lo, hi);
    box.far_depth = far_depth;
    gl_Position = vec4(0.0);
}
