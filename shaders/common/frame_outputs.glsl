// Render targets of stages 2 and 3 (src/cutaway/frame_targets.h).
layout(location = 0) out vec4 out_colour;        // lit colour
layout(location = 1) out vec4 out_normal_depth;  // model camera eye-space normal, linear depth
layout(location = 2) out uvec2 out_id;           // compact cell + 1, pixel flags
layout(location = 3) out vec4 out_face_plane;    // world face normal, w = 1 + face class (secondaries, 0 elsewhere)

const uint flag_primary = 1u;
const uint flag_cut_fill = 2u;     // a cell's inside seen through the cut
const uint flag_border = 4u;       // border line where a face meets the cut
const uint flag_edge = 8u;         // cell edge line
const uint flag_shell_cut = 16u;   // border line on a shell face

uniform mat4 model_view;  // the model camera's view matrix

void write_frame(vec3 colour, vec3 normal, vec3 world, uint compact_cell, uint flags) {
    out_face_plane = vec4(0.0);
    out_colour = vec4(colour, 1.0);
    out_normal_depth = vec4(normalize(mat3(model_view) * normal), -(model_view * vec4(world, 1.0)).z);
    out_id = uvec2(compact_cell + 1u, flags);
}
