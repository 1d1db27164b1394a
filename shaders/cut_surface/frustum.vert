#version 450 core
// Stage 1, frustum union: one point per primary cell. The cell's 8 corners go to the cut
// camera's eye space; the box is kept in perspective-divided coordinates (u = x/s, v = y/s,
// s = depth along the view axis), where view rays are lines of constant (u, v), so the box's
// (u, v) range covers every pixel the cell covers.
#include "common/shared_constants.h"
#include "common/grid.glsl"

#ifdef CLUSTERS
// One point per cluster of primaries (cut_surface/primary_clusters.h): its cells' compact indices
// are cluster_cells[first .. first + count), (first, count) = cluster_ranges[point].
layout(binding = tex_cluster_ranges) uniform usamplerBuffer cluster_ranges;
layout(binding = tex_cluster_cells) uniform usamplerBuffer cluster_cells;
#elif defined(OPENING)
// Cells whose cut opens or closes over an animation's frames (cut_surface/opening_cut.h): the
// compact cell and, as float bits, the share of the depth from the rim to its back face reached.
// Bit 31 of the cell: it opens beside the cut (its face neighbours' cut reaches over it).
layout(std430, binding = ssbo_opening_cells) readonly buffer OpeningCells { uvec2 opening_cells[]; };
uniform vec3 model_min;  // render-space bounds of the model
uniform vec3 model_max;
uniform vec2 wall_angle;
#include "cut_surface/wall_slope.glsl"
#else
layout(std430, binding = ssbo_primary_cells) readonly buffer PrimaryCells { uint primary_cells[]; };
#endif

uniform mat4 cut_view;
uniform float near_plane;

out CellBox {
    vec4 uv_box;       // u0, v0, u1, v1
    float far_depth;   // largest corner depth s
    float opening;     // 1, or for OPENING the cell's share of the depth behind the entry
    float entry_depth; // OPENING: depth s where the ray through the box's centre enters the model's bounds
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
    box.opening = 1.0;
    box.entry_depth = near_plane;
#ifdef CLUSTERS
    uvec2 range = texelFetch(cluster_ranges, gl_VertexID).rg;
    for (uint n = 0u; n < range.y; ++n) add_cell(texelFetch(cluster_cells, int(range.x + n)).r);
#elif defined(OPENING)
    uvec2 entry = opening_cells[gl_VertexID];
    add_cell(entry.x & 0x7fffffffu);
    box.opening = uintBitsToFloat(entry.y);
    // The opening moves the back face along the view rays from where they enter the model (the
    // bounding box's near side: for a layered model, its top) to the cell, so the cut's
    // cross-section where the rays enter grows from nothing with the square of the opening.
    mat4 eye_to_render = inverse(cut_view);
    vec3 origin = eye_to_render[3].xyz;
    vec3 direction = mat3(eye_to_render) * vec3(0.5 * (lo + hi), -1.0);  // s grows by 1 per unit of t
    vec3 t0 = (model_min - origin) / direction, t1 = (model_max - origin) / direction;
    vec3 nearest = min(t0, t1);
    box.entry_depth = max(max(nearest.x, nearest.y), max(nearest.z, near_plane));
    // Beside the cut the neighbours' walls reach over the cell down to about the depth a wall
    // falls across the cell's width (u per depth: wall_slope / depth, frustum.geom): the cut
    // opens from there, where it starts to uncover anything. What it uncovers there grows faster
    // than the depth (a wall seen edge-on sweeps a band of the screen): the opening, the square
    // root of the frames' share for a cut opening from the top, is raised to the power 3/4 here,
    // which spread the flips of a cell entering beside SPE9's water most evenly over 4 frames (an
    // empirical choice on that case: powers 1/2, 1 and 2 left 0.39, 0.32 and 0.50 of the flips in
    // the largest frame, 3/4 left 0.28).
    if ((entry.x & 0x80000000u) != 0u) {
        vec2 drop = (hi - lo) * far_depth / max(wall_slope(hi, 1.0, wall_angle), vec2(1e-6));
        box.entry_depth = max(box.entry_depth, far_depth - max(drop.x, drop.y));
    }
#else
    add_cell(primary_cells[gl_VertexID]);
#endif
    box.uv_box = vec4(lo, hi);
    box.far_depth = far_depth;
    gl_Position = vec4(0.0);
}
