#version 450 core
// Stage 3: primary cells, drawn whole (never clipped), with their own edge colour: a lighter
// shade of the cell's colour (secondaries' edges are darker), so primaries keep their colour.
#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/frame_outputs.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform float line_width;
const float primary_edge_lightening = 0.45;  // edge colour: this far from the cell's colour to white

void main() {
    vec3 colour = lit(cell_colour(v_in.compact_cell), v_in.face_normal, v_in.world_position);
    float edge_opacity = face_edge_opacity(v_in.edge_distance, line_width);
    colour = mix(colour, mix(colour, vec3(1.0), primary_edge_lightening), edge_opacity);
    uint flags = flag_primary | (edge_opacity > 0.5 ? flag_edge : 0u);
    write_frame(colour, v_in.face_normal, v_in.world_position, v_in.compact_cell, flags);
}
