#version 450 core
// Per word of 32 cells, from its offsets (scan_primary_counts.comp): the compact indices of its
// primary cells and the face records of their drawn faces (build_face_lists' order).
#include "common/shared_constants.h"
layout(local_size_x = 64) in;

#include "selection/primary_words.glsl"

layout(std430, binding = ssbo_primary_cells_out) writeonly buffer PrimaryCells { uint primary_cells[]; };
layout(std430, binding = ssbo_primary_faces_out) writeonly buffer PrimaryFaces { uint primary_faces[]; };

void main() {
    uint word = word_index();
    if (word >= word_count()) return;
    uvec2 next = word_counts[word];
    for (uint rest = primary_bits[word]; rest != 0u; rest &= rest - 1u) {
        uint compact = 32u * word + uint(findLSB(rest));
        primary_cells[next.x++] = compact;
        for (uint side = 0u; side < 6u; ++side)
            if (primary_face_drawn(compact, side)) primary_faces[next.y++] = pack_face_record(compact, side, face_class(compact, side));
    }
}
