// Render targets of stages 2 and 3 (src/cutaway/frame_targets.h).
layout(location = 0) out vec4 out_colour;        // lit colour
layout(location = 1) out vec4 out_normal_depth;  // model camera eye-space normal, linear depth
layout(location = 2) out uvec2 out_id;           // compact cell + 1, pixel flags
layout(location = 3) out vec4 out_face_plane;    // world face normal, w = 1 + face class (secondaries, 0 elsewhere)

#include "common/pixel_flags.glsl"

uniform mat4 model_view;  // the model camera's view matrix

// `linear_depth`: along the model camera's axis.
void write_frame_at_depth(vec3 colour, vec3 normal, float linear_depth, uint compact_cell, uint flags) {
    out_face_plane = vec4(0.0);
    out_colour = vec4(colour, 1.0);
    out_normal_depth = vec4(normalize(mat3(model_view) * normal), linear_depth);
    out_id = uvec2(compact_cell + 1u, flags);
}

void write_frame(vec3 colour, vec3 normal, vec3 world, uint compact_cell, uint flags) {
    write_frame_at_depth(colour, normal, -(model_view * vec4(world, 1.0)).z, compact_cell, flags);
}
