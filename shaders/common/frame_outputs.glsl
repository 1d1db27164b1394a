// Render targets of stages 2 and 3 (src/cutaway/frame_targets.h).
layout(location = 0) out vec4 out_colour;        // lit colour
layout(location = 1) out uvec2 out_normal_depth;  // model camera eye-space normal, linear depth (common/packed_normal.glsl)
layout(location = 2) out uvec2 out_id;            // compact cell + 1, pixel flags
layout(location = 3) out uvec2 out_face_plane;    // world face normal, 1 + face class (secondaries; 0, 0 elsewhere), packed

#include "common/shared_constants.h"
#include "common/packed_normal.glsl"

#include "common/cameras.glsl"  // model_view: the model camera's view matrix

// `linear_depth`: along the model camera's axis.
void write_frame_at_depth(vec3 colour, vec3 normal, float linear_depth, uint compact_cell, uint flags) {
    out_face_plane = uvec2(0u);
    out_colour = vec4(colour, 1.0);
    out_normal_depth = pack_normal_and(normalize(mat3(model_view) * normal), linear_depth);
    out_id = uvec2(compact_cell + 1u, flags);
}

void write_frame(vec3 colour, vec3 normal, vec3 world, uint compact_cell, uint flags) {
    write_frame_at_depth(colour, normal, -(model_view * vec4(world, 1.0)).z, compact_cell, flags);
}
