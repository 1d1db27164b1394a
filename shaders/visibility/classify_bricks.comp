#version 450 core
// First step of the per-frame face selection (SPEC.md section 6): one invocation per IJK brick
// tests the brick's box against the model camera's frustum and the cut pyramid and stores its
// class for visibility/cull_cells.comp; bricks that give no face are counted here.
#include "common/shared_constants.h"
layout(local_size_x = 64) in;

#include "visibility/classify.glsl"

layout(std430, binding = ssbo_brick_begin) readonly buffer BrickBegin { uint brick_begin[]; };  // brick_count + 1
layout(std430, binding = ssbo_brick_boxes) readonly buffer BrickBoxes { vec4 brick_boxes[]; };  // min, max per brick
#include "visibility/culling_counters.glsl"
layout(std430, binding = ssbo_brick_classes) writeonly buffer BrickClasses { uint brick_classes[]; };

uniform uint brick_count;

void main() {
    uint brick = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
    if (brick >= brick_count) return;
    int where = classify_box(brick_boxes[2u * brick].xyz, brick_boxes[2u * brick + 1u].xyz);
    brick_classes[brick] = uint(where);
    if (gives_nothing(where)) {
        atomicAdd(bricks_culled, 1u);
        atomicAdd(cells_culled, brick_begin[brick + 1u] - brick_begin[brick]);
    }
}
