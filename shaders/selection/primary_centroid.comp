#version 450 core
// Sums of the primary cells' centres (mean of the 8 corners, render space), one partial sum per
// workgroup of 256 primaries; the CPU adds the partial sums in double
// (src/cutaway/selection/primary_centroid.h). Workgroups spread over Y beyond 65535 along X.
#include "common/shared_constants.h"
layout(local_size_x = 256) in;

#include "common/grid.glsl"

layout(std430, binding = ssbo_primary_cells) readonly buffer PrimaryCells { uint primary_cells[]; };
layout(std430, binding = ssbo_centroid_partial_sums) writeonly buffer PartialSums { vec4 partial_sums[]; };  // xyz: sum, w: count

uniform uint primary_count;

shared vec4 sums[256];

void main() {
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint n = group * 256u + gl_LocalInvocationID.x;
    vec4 mine = vec4(0.0);
    if (n < primary_count) {
        uint cell = primary_cells[n];
        vec3 sum = vec3(0.0);
        for (uint c = 0u; c < 8u; ++c) sum += corner_position(cell, c);
        mine = vec4(sum / 8.0, 1.0);
    }
    sums[gl_LocalInvocationID.x] = mine;
    barrier();
    for (uint half_size = 128u; half_size > 0u; half_size >>= 1) {
        if (gl_LocalInvocationID.x < half_size) sums[gl_LocalInvocationID.x] += sums[gl_LocalInvocationID.x + half_size];
        barrier();
    }
    if (gl_LocalInvocationID.x == 0u) partial_sums[group] = sums[0];
}
