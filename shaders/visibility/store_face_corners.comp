#version 450 core
// Once per model, for the plain frame (src/cutaway/exposed_surface.h): the 4 corners of each
// exposed face in face_corners order, so the plain frame's vertices read 4 stored positions
// instead of rebuilding 4 corners from pillars and depths each (common/face.vert STORED_CORNERS).
#include "common/shared_constants.h"
layout(local_size_x = 64) in;

#include "common/grid.glsl"

layout(std430, binding = ssbo_faces) readonly buffer Faces { uint faces[]; };
layout(std430, binding = ssbo_face_corners) writeonly buffer Corners { float corners[]; };  // 12 floats per face

uniform uint face_count;

void main() {
    uint face = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
    if (face >= face_count) return;
    uint record = faces[face];
    uint cell = face_record_cell(record), side = face_record_side(record);
    for (uint k = 0u; k < 4u; ++k) {
        vec3 q = corner_position(cell, face_corners[side * 4u + k]);
        for (uint c = 0u; c < 3u; ++c) corners[12u * face + 3u * k + c] = q[c];
    }
}
