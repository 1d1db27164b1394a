#version 450 core
// Primary bits from the property range (and an optional IJK box): a cell is primary when its
// value (the colouring values, common/grid.glsl) lies in [range.x, range.y]. NaN never does.
layout(local_size_x = 64) in;

#include "selection/primary_words.glsl"

uniform vec2 value_range;
uniform bool use_box;
uniform ivec3 box_min, box_max;  // inclusive IJK box (may reach outside the grid, or be empty)

void main() {
    uint word = word_index();
    if (word >= word_count()) return;
    uint bits = 0u;
    for (uint b = 0u; b < 32u; ++b) {
        uint compact = 32u * word + b;
        if (compact >= active_cells) break;
        float value = cell_value(compact);
        bool primary = value >= value_range.x && value <= value_range.y;
        if (primary && use_box) {
            ivec3 c = ivec3(compact_cell_ijk(compact));
            primary = all(greaterThanEqual(c, box_min)) && all(lessThanEqual(c, box_max));
        }
        if (primary) bits |= 1u << b;
    }
    primary_bits[word] = bits;
}
