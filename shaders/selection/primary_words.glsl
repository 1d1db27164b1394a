// The primary selection on the GPU (src/cutaway/selection/gpu_primary_selection.h): one
// invocation per word of 32 active cells, in compact order, so every list comes out in the order
// the CPU reference builds it (ascending cell, then side).
#include "common/shared_constants.h"
#include "common/grid.glsl"

layout(std430, binding = ssbo_cell_face_classes) readonly buffer CellFaceClasses { uint cell_face_classes[]; };  // 16 bits per cell, 2 per side
layout(std430, binding = ssbo_primary_bits) buffer PrimaryBits { uint primary_bits[]; };  // 1 bit per compact cell
// Per 32 Eclipse cells: their active bits, and the active cells before them (gpu_primary_selection.cpp).
layout(std430, binding = ssbo_active_words) readonly buffer ActiveWords { uvec2 active_words[]; };
// Per word: primary cells and primary faces it holds; after the scan, the first index of each.
layout(std430, binding = ssbo_word_counts) buffer WordCounts { uvec2 word_counts[]; };

uniform uint active_cells;
uniform uvec3 grid_dims;  // NX, NY, NZ
uniform uint plane_slots_per_layer;  // corner-plane slots per layer: 1 compact ZCORN, 2 full

const uint no_cell = 0xffffffffu;

uint word_count() { return (active_cells + 31u) / 32u; }

// This invocation's word (dispatches spread over Y beyond 65535 workgroups along X).
uint word_index() { return gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x; }

// IJK of an active cell from its top-face texel in the grid's cell records (common/grid.glsl:
// ((slots k NY + j) NX + i), src/cutaway/grid_buffers.cpp), so no Eclipse index per cell is kept.
uvec3 compact_cell_ijk(uint compact) {
    uint texel = texelFetch(cell_texels, int(compact)).g;
    uint row = texel / grid_dims.x;
    return uvec3(texel % grid_dims.x, row % grid_dims.y, row / (plane_slots_per_layer * grid_dims.y));
}

// Compact index of Eclipse cell `cell` (its rank among the active cells), or no_cell if inactive.
uint compact_of_eclipse(uint cell) {
    uvec2 word = active_words[cell >> 5];
    uint bit = 1u << (cell & 31u);
    return (word.x & bit) == 0u ? no_cell : word.y + uint(bitCount(word.x & (bit - 1u)));
}

bool is_primary(uint compact) { return compact != no_cell && ((primary_bits[compact >> 5] >> (compact & 31u)) & 1u) != 0u; }

uint face_class(uint compact, uint side) { return (cell_face_classes[compact >> 1] >> (16u * (compact & 1u) + 2u * side)) & 3u; }

// Compact index of the active neighbour across `side` (I-, I+, J-, J+, K-, K+), or no_cell.
uint neighbour(uint compact, uint side) {
    ivec3 c = ivec3(compact_cell_ijk(compact));
    c[side >> 1] += (side & 1u) == 0u ? -1 : 1;
    if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(grid_dims)))) return no_cell;
    return compact_of_eclipse(uint(c.x) + grid_dims.x * (uint(c.y) + grid_dims.y * uint(c.z)));
}

// A primary cell draws every face except an interior one shared with another primary (hidden
// inside the primary cluster), as build_face_lists does.
bool primary_face_drawn(uint compact, uint side) {
    return face_class(compact, side) != face_class_interior || !is_primary(neighbour(compact, side));
}
