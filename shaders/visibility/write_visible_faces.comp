#version 450 core
// The face records of visibility/cull_cells.comp's selection, one invocation per brick, written
// brick by brick and, within a brick, cell by cell and side by side (the all-faces list's order
// for the cells of one IJK column): each brick starts at its offset from visibility/scan_bricks.comp.
// Records past face_capacity are dropped (the draw clamps its count to it).
#include "common/shared_constants.h"
layout(local_size_x = 64) in;

#include "common/grid.glsl"

layout(binding = tex_face_classes) uniform usamplerBuffer face_class_texels;   // per cell: 2 bits per side
layout(binding = tex_brick_cells) uniform usamplerBuffer brick_cell_texels;   // compact cells, brick by brick
layout(binding = tex_brick_begin) uniform usamplerBuffer brick_begin_texels;  // first cell of each brick, brick_count + 1
layout(std430, binding = ssbo_visible_faces) writeonly buffer VisibleFaces { uint visible_faces[]; };
layout(std430, binding = ssbo_cell_face_masks) readonly buffer CellFaceMasks { uint cell_face_masks[]; };
layout(std430, binding = ssbo_brick_face_counts) readonly buffer BrickFaceCounts { uint brick_face_counts[]; };
layout(std430, binding = ssbo_brick_offsets) readonly buffer BrickOffsets { uint brick_offsets[]; };
layout(std430, binding = ssbo_block_offsets) readonly buffer BlockOffsets { uint block_offsets[]; };

uniform uint brick_count;
uniform uint scan_block;
uniform uint face_capacity;

uint texel(usamplerBuffer texels, uint index) { return texelFetch(texels, int(index)).r; }

void main() {
    uint brick = gl_WorkGroupID.y * gl_NumWorkGroups.x * 64u + gl_GlobalInvocationID.x;
    if (brick >= brick_count || brick_face_counts[brick] == 0u) return;
    uint at = block_offsets[brick / scan_block] + brick_offsets[brick];
    uint last = texel(brick_begin_texels, brick + 1u);
    for (uint slot = texel(brick_begin_texels, brick); slot < last; ++slot) {
        uint mask = (cell_face_masks[slot >> 2] >> (8u * (slot & 3u))) & 0x3fu;
        if (mask == 0u) continue;
        uint cell = texel(brick_cell_texels, slot);
        uint classes = texel(face_class_texels, cell);
        for (uint side = 0u; side < 6u; ++side) {
            if ((mask & (1u << side)) == 0u) continue;
            if (at < face_capacity) visible_faces[at] = pack_face_record(cell, side, (classes >> (2u * side)) & 3u);
            ++at;
        }
    }
}
