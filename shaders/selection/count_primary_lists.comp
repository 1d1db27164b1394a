#version 450 core
// Per word of 32 cells: how many primary cells and primary faces it contributes.
layout(local_size_x = 64) in;

#include "selection/primary_words.glsl"

void main() {
    uint word = word_index();
    if (word >= word_count()) return;
    uint bits = primary_bits[word];
    uint faces = 0u;
    for (uint rest = bits; rest != 0u; rest &= rest - 1u) {
        uint compact = 32u * word + uint(findLSB(rest));
        for (uint side = 0u; side < 6u; ++side)
            if (primary_face_drawn(compact, side)) ++faces;
    }
    word_counts[word] = uvec2(bitCount(bits), faces);
}
