#version 450 core
// Exclusive prefix sums of the faces each brick gives (visibility/cull_cells.comp's counts), in
// two levels so that no invocation walks more than scan_block bricks: BLOCKS unset, one
// invocation per block of scan_block bricks writes each brick's offset within its block and the
// block's total; BLOCKS, a single invocation turns the block totals into the blocks' offsets and
// writes the sum of all into faces_requested (the indirect draw's count, finish_culling.comp).
// visibility/write_visible_faces.comp adds the two offsets.
#include "common/shared_constants.h"
layout(local_size_x = 64) in;

layout(std430, binding = ssbo_brick_offsets) buffer BrickOffsets { uint brick_offsets[]; };  // within the block
layout(std430, binding = ssbo_block_offsets) buffer BlockOffsets { uint block_offsets[]; };

uniform uint scan_block;  // bricks per block
#ifdef BLOCKS
#include "visibility/culling_counters.glsl"
uniform uint block_count;

void main() {
    if (gl_GlobalInvocationID.x != 0u) return;
    uint sum = 0u;
    for (uint b = 0u; b < block_count; ++b) {
        uint total = block_offsets[b];
        block_offsets[b] = sum;
        sum += total;
    }
    faces_requested = sum;
}
#else
layout(std430, binding = ssbo_brick_face_counts) readonly buffer BrickFaceCounts { uint brick_face_counts[]; };
uniform uint brick_count;

void main() {
    uint block = gl_WorkGroupID.y * gl_NumWorkGroups.x * 64u + gl_GlobalInvocationID.x;
    uint first = block * scan_block;
    if (first >= brick_count) return;
    uint last = min(first + scan_block, brick_count);
    uint sum = 0u;
    for (uint b = first; b < last; ++b) {
        brick_offsets[b] = sum;
        sum += brick_face_counts[b];
    }
    block_offsets[block] = sum;
}
#endif
