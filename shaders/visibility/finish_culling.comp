#version 450 core
// After visibility/cull_cells.comp: one indexed draw command per chunk of quads
// (src/cutaway/quad_draw.h) from the faces selected, clamped to the capacity of the face buffer
// (an overflow shows as faces_requested > capacity). Chunks past the last face draw nothing.
#include "common/shared_constants.h"
layout(local_size_x = 64) in;

#include "visibility/culling_counters.glsl"

struct DrawElementsIndirectCommand {
    uint count;
    uint instance_count;
    uint first_index;
    int base_vertex;
    uint base_instance;
};
layout(std430, binding = ssbo_draw_commands) writeonly buffer DrawCommands { DrawElementsIndirectCommand commands[]; };

uniform uint face_capacity;
uniform uint chunk_count;
uniform uint quads_per_chunk;

void main() {
    uint chunk = gl_GlobalInvocationID.x;
    if (chunk >= chunk_count) return;
    uint faces = min(faces_requested, face_capacity);
    uint first = chunk * quads_per_chunk;
    uint in_chunk = faces > first ? min(faces - first, quads_per_chunk) : 0u;
    commands[chunk] = DrawElementsIndirectCommand(6u * in_chunk, 1u, 0u, int(4u * first), 0u);
}
