#version 450 core
// Stage 3: a well tube, never clipped by the cut (as primaries), lit as the cells are. Its pixels
// show no cell (id 0) and carry flag_well with the well's index.
#include "common/lighting.glsl"
#include "common/frame_outputs.glsl"

in vec3 v_world;
in vec3 v_normal;
in vec3 v_colour;
flat in uint v_well;

void main() {
    uint flags = flag_well | (v_well << well_index_shift);
    write_frame(lit(v_colour, v_normal, v_world), v_normal, v_world, 0u, flags);
    out_id = uvec2(0u, flags);  // no cell: the cell-id image reports none here
}
