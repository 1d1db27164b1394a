#version 450 core
// The plain frame (`render --baseline`): the model's faces shaded with their cell edges, no cut.
// Nothing is discarded, so the depth test runs before the shader (early depth: hidden fragments
// are never shaded), and only the colour and the cell id are written (the scene's plain
// framebuffer, src/cutaway/frame_targets.h, has no other colour attachment).
layout(early_fragment_tests) in;

#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/frame_outputs.glsl"

in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform float line_width;  // pixels

void main() {
    vec3 colour = lit(cell_colour(v_in.compact_cell), v_in.face_normal, v_in.world_position);
    float edge_opacity = face_edge_opacity(v_in.edge_distance, line_width);
    out_colour = vec4(mix(colour, line_colour_on(colour), edge_opacity), 1.0);
    out_id = uvec2(v_in.compact_cell + 1u, edge_opacity > 0.5 ? flag_edge : 0u);
}
