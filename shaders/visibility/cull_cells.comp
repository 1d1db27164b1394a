#version 450 core
// Per-frame choice of the secondary faces that can reach a pixel (SPEC.md section 6). Each IJK
// brick's box is tested first, then each of its cells (8 corners)
// against the model camera's frustum and the min/max pyramid of the cut depth:
//   outside the frustum, or entirely in front of the cut (every fragment discarded): nothing;
//   entirely behind the cut (every fragment kept): its exposed faces seen from outside;
//   straddling the cut: every face the all-faces pass would draw for it, less each face that is
//   itself outside the frustum or entirely in front of the cut (its own 4 corners tested: at
//   petra's default camera this left 12M of the 21M fragments stage 2 rasterised, 81% of which
//   the cut discarded).
// Each secondary cell's surviving sides go into its byte of cell_face_masks (by its slot in the
// brick-ordered cell list) and are counted per brick (visibility/scan_bricks.comp sums them);
// visibility/write_visible_faces.comp then writes the records in brick and cell order, so that
// the draw order, and with it which of two coincident faces wins the depth test, does not depend
// on the order the GPU's invocations ran in. The CPU reads nothing back to draw. The bricks'
// classes come from visibility/classify_bricks.comp.
#include "common/shared_constants.h"
layout(local_size_x = 64) in;

#include "common/grid.glsl"
#include "common/face_frame.glsl"
#include "visibility/classify.glsl"

// Read as buffer textures: on llvmpipe a storage-buffer load at an index that varies across the
// SIMD lanes runs lane by lane, a texel fetch is one gather (the selection ran faster so).
layout(binding = tex_face_classes) uniform usamplerBuffer face_class_texels;   // per cell: 2 bits per side
layout(binding = tex_primary_bits) uniform usamplerBuffer primary_bit_texels;  // 1 bit per compact cell
layout(binding = tex_brick_cells) uniform usamplerBuffer brick_cell_texels;   // compact cells, brick by brick
layout(binding = tex_brick_begin) uniform usamplerBuffer brick_begin_texels;  // first cell of each brick, brick_count + 1
layout(binding = tex_brick_classes) uniform usamplerBuffer brick_class_texels;  // classify_bricks.comp
#include "visibility/culling_counters.glsl"
layout(std430, binding = ssbo_cell_face_masks) buffer CellFaceMasks { uint cell_face_masks[]; };  // 4 slots per uint, cleared per frame
layout(std430, binding = ssbo_brick_face_counts) buffer BrickFaceCounts { uint brick_face_counts[]; };  // cleared per frame

uniform uint brick_count;
uniform uint bricks_per_group;  // consecutive bricks a workgroup takes in turn

uint texel(usamplerBuffer texels, uint index) { return texelFetch(texels, int(index)).r; }

bool is_primary(uint cell) { return ((texel(primary_bit_texels, cell >> 5) >> (cell & 31u)) & 1u) != 0u; }

// The faces one secondary cell (at `slot` of `brick`, whose class is `brick_class`) gives, as a
// mask of sides. The cell's 8 corners are rebuilt once, and only when a face or the cell's own
// test needs them. The cell is counted in `counts` (culled, behind, straddling), which the caller
// adds to the counters once for all its bricks.
void select_cell(uint cell, uint slot, uint brick, int brick_class, inout uvec3 counts) {
    if (is_primary(cell)) return;  // primaries are drawn by stage 3
    uint classes = texel(face_class_texels, cell);
    const uint all_interior = 0x555u;  // face_class_interior on all 6 sides
    if (brick_class == behind && classes == all_interior) return;  // behind the cut, nothing exposed
    vec3 p[8];
    for (uint k = 0u; k < 8u; ++k) p[k] = corner_position(cell, k);
    int cell_class = brick_class == behind ? behind : classify(p);
    counts += uvec3(cell_class == culled || cell_class == in_front, cell_class == behind, cell_class == straddling);
    if (gives_nothing(cell_class)) return;
    uint mask = 0u;
    for (uint side = 0u; side < 6u; ++side) {
        uint face_class = (classes >> (2u * side)) & 3u;
        bool exposed = face_class != face_class_interior;
        if (cell_class == behind && !exposed) continue;
        FaceFrame f = face_frame_from_corners(p, cell, side, eye_position);
        // Behind the cut a cell shows only its exposed faces seen from outside (a face both of
        // whose triangles face away lies behind the cell's own front); through the cut, whatever
        // the draw keeps (interior faces only from inside their cell); in front of it, the
        // exposed faces seen from inside (keep_rear_faces).
        bool keep = !f.collapsed && (cell_class == straddling ? (exposed || f.back_facing)
                                     : cell_class == in_front ? exposed && f.back_facing
                                                              : f.any_triangle_front_facing);
        if (keep && cell_class == straddling) {  // the face's own test; in front, as for a cell
            vec3 q[8] = vec3[8](f.q[0], f.q[1], f.q[2], f.q[3], f.q[0], f.q[0], f.q[0], f.q[0]);
            int face_where = classify_first(q, 4);
            keep = face_where == culled ? false : face_where == in_front ? exposed && f.back_facing && keep_rear_faces : true;
        }
        if (keep) mask |= 1u << side;
    }
    if (mask == 0u) return;
    atomicOr(cell_face_masks[slot >> 2], mask << (8u * (slot & 3u)));
    atomicAdd(brick_face_counts[brick], uint(bitCount(mask)));
}

// No shared memory and no barrier(): llvmpipe runs barrier() by switching between the
// invocations of a workgroup, which costs more than the test itself. A workgroup takes
// bricks_per_group bricks in turn, one cell per invocation (a brick has at most 64 cells): on
// llvmpipe each workgroup has a fixed cost before it does anything, so one per brick (3,250 on
// sapphire) cost more than the selection itself. An invocation adds its cells to the counters once
// at the end: an atomic per cell on the same three words made the pass slower (scale-1m at
// 1080p, medians of 8 frames in 3 alternating runs).
void main() {
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint first = group * bricks_per_group;
    uint last = min(first + bricks_per_group, brick_count);
    uvec3 counts = uvec3(0u);
    for (uint brick = first; brick < last; ++brick) {
        int brick_class = int(texel(brick_class_texels, brick));
        if (gives_nothing(brick_class)) continue;
        uint slot = texel(brick_begin_texels, brick) + gl_LocalInvocationIndex;
        if (slot < texel(brick_begin_texels, brick + 1u))
            select_cell(texel(brick_cell_texels, slot), slot, brick, brick_class, counts);
    }
    if (counts.x != 0u) atomicAdd(cells_culled, counts.x);
    if (counts.y != 0u) atomicAdd(cells_behind, counts.y);
    if (counts.z != 0u) atomicAdd(cells_straddling, counts.z);
}
