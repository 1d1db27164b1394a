#version 450 core
// Stage 3: primary cells, drawn whole (never clipped), with their own edge colour.
#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/frame_outputs.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform float line_width;
uniform vec3 primary_edge_colour;

void main() {
    vec3 colour = lit(cell_colour(v_in.compact_cell), v_in.face_normal, v_in.world_position);
    float edge = min(min(v_in.edge_distance.x, v_in.edge_distance.y), min(v_in.edge_distance.z, v_in.edge_distance.w));
    float edge_opacity = line_opacity(edge, line_width);
    colour = mix(colour, primary_edge_colour, edge_opacity);
    uint flags = flag_primary | (edge_opacity > 0.5 ? flag_edge : 0u);
    write_frame(colour, v_in.face_normal, v_in.world_position, v_in.compact_cell, flags);
}
