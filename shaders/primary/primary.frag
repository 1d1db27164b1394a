#version 450 core
// Stage 3: primary cells, drawn whole (never clipped), with their own edge colour: a lighter
// shade of the cell's colour (secondaries' edges are darker), so primaries keep their colour.
// Variant HIDDEN_WALLS (--only secondaries): the far walls of the hidden primaries where they are
// the model's shell (common/face.vert SHELL_BACKS), in a neutral grey without lines, as cut fill:
// there nothing of the secondaries lies behind a hidden primary, and the wall keeps the hole it
// leaves from showing the background. Elsewhere the secondaries behind show, as before.
#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/frame_outputs.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform float line_width;
const float primary_edge_lightening = 0.45;  // edge colour: this far from the cell's colour to white

#ifdef HIDDEN_WALLS
const vec3 hidden_wall_grey = vec3(0.78);

void main() {
    // Seen from inside its cell: the wall faces the camera against its outward normal.
    vec3 normal = -v_in.face_normal;
    write_frame(lit(hidden_wall_grey, normal, v_in.world_position), normal, v_in.world_position, v_in.compact_cell,
                flag_cut_fill);
}
#else
void main() {
    vec3 colour = lit(cell_colour(v_in.compact_cell), v_in.face_normal, v_in.world_position);
    float edge_opacity = face_edge_opacity(v_in.edge_distance, line_width);
    colour = mix(colour, mix(colour, vec3(1.0), primary_edge_lightening), edge_opacity);
    uint flags = flag_primary | (edge_opacity > 0.5 ? flag_edge : 0u);
    write_frame(colour, v_in.face_normal, v_in.world_position, v_in.compact_cell, flags);
}
#endif
