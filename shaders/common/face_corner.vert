#version 450 core
// Depth-only face passes (the rear shell, cut_surface/seed_geometry.frag, with the primaries'
// faces at the far plane, cut_surface/far_depth.frag; the shell contours, primary/shell_depth.frag;
// the cut seeds from the primaries' faces, --seeds geometry): one face record -> one indexed quad
// as in common/face.vert, but each vertex rebuilds only its own corner. These passes read no
// normal, edge distance or cell. Where they keep one side only (the rear shell, the contours),
// the facing test is the rasteriser's, per triangle (GL_CULL_FACE): the faces come split by the
// way their corners (face_corners order) turn seen from outside their cell (GridBuffers::
// WoundFaces), each part drawn with its own glFrontFace, so a vertex keeps the corner
// common/face.vert gives it and the triangles rasterise to the same pixels and depths.
// common/face.vert rebuilds all 4 corners per vertex (16 per face) for its edge distances and
// face-wide facing tests; on llvmpipe, where the vertex stage is serial, that made these two
// passes vertex-bound (sapphire: 480x270 instead of 1920x1080 saved little of their time).
#include "common/shared_constants.h"
#include "common/grid.glsl"
#include "common/cameras.glsl"

layout(std430, binding = ssbo_faces) readonly buffer Faces { uint faces[]; };


// The same corner, projected by the same product, as common/face.vert.
invariant gl_Position;

out FaceVaryings {
#include "common/face_varyings.glsl"
} v_out;

void main() {
    uint record = faces[gl_VertexID / 4];
    uint cell = face_record_cell(record);
    vec3 q = corner_position(cell, face_corners[face_record_side(record) * 4u + uint(gl_VertexID) % 4u]);
    gl_Position = view_projection * vec4(q, 1.0);
    v_out.cut_eye_depth = -(model_view * vec4(q, 1.0)).z;  // the depth seed_geometry.frag writes
}
