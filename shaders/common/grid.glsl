// Corner-point geometry on the GPU: corners rebuilt from pillars and per-cell corner depths
// (src/cutaway/grid_layout.h describes the buffers). Render space: X east, Y north, Z up.
// Read through buffer textures (src/cutaway/grid_buffers.h says why).
#include "common/shared_constants.h"
layout(binding = tex_pillars) uniform samplerBuffer pillar_texels;        // top, bottom per pillar
layout(binding = tex_corner_depths) uniform samplerBuffer corner_depth_texels;  // per depth plane slot and (i, j): 4 corner depths
layout(binding = tex_cells) uniform usamplerBuffer cell_texels;        // pillar of corner 0 | flip bit, top-face texel
layout(binding = tex_cell_values) uniform samplerBuffer cell_value_texels;  // property per active cell

uniform uvec2 grid_size;  // NX, NY
uniform float up_sign;    // -1 when z is depth
uniform float z_scale;    // vertical exaggeration
// A cell's value = x + y x its texel: (0, 1) for float values; a 16-bit code's offset and span
// (src/cutaway/quantised_values.h) when the values were sent at 16 bits.
uniform vec2 value_decoding = vec2(0.0, 1.0);

float cell_value(uint compact_cell) {
    return value_decoding.x + value_decoding.y * texelFetch(cell_value_texels, int(compact_cell)).r;
}

// Face record (src/cutaway/grid_layout.h pack_face): bits 0-26 compact cell, 27-29 side, 30-31 class.
uint face_record_cell(uint record) { return record & 0x7ffffffu; }
uint face_record_side(uint record) { return (record >> 27) & 7u; }
uint face_record_class(uint record) { return record >> 30; }
uint pack_face_record(uint cell, uint side, uint face_class) { return cell | (side << 27) | (face_class << 30); }

const uint face_class_interior = 1u;
const uint face_class_fault = 2u;
const uint face_class_shell = 3u;

// Corners of each face (I-, I+, J-, J+, K-, K+) in an order whose diagonal cross product points
// out of a cell with positive signed volume in model (x, y, z) space.
const uint face_corners[24] = uint[](0u, 4u, 6u, 2u,  1u, 3u, 7u, 5u,  0u, 1u, 5u, 4u,
                                     2u, 6u, 7u, 3u,  0u, 2u, 3u, 1u,  4u, 5u, 7u, 6u);

vec3 corner_position(uint compact_cell, uint corner) {
    // The pillar index is stored, not derived from the cell's I, J: integer division is slow on
    // SIMD CPUs (llvmpipe) and this runs 4 times per vertex.
    uvec2 record = texelFetch(cell_texels, int(compact_cell)).rg;
    uint pillar = (record.r & 0x7fffffffu) + ((corner >> 1) & 1u) * (grid_size.x + 1u) + (corner & 1u);
    vec3 top = texelFetch(pillar_texels, int(2u * pillar)).xyz;
    vec3 bottom = texelFetch(pillar_texels, int(2u * pillar + 1u)).xyz;
    // The bottom face's plane slot follows the top's (grid_buffers.cpp upload_corner_planes).
    uint plane_texel = record.g + (corner >> 2) * grid_size.x * grid_size.y;
    float z = texelFetch(corner_depth_texels, int(plane_texel))[corner & 3u];
    float dz = bottom.z - top.z;
    vec2 xy = dz == 0.0 ? top.xy : top.xy + ((z - top.z) / dz) * (bottom.xy - top.xy);
    return vec3(xy, up_sign * z * z_scale);
}

bool cell_normals_flipped(uint compact_cell) { return (texelFetch(cell_texels, int(compact_cell)).r & 0x80000000u) != 0u; }
