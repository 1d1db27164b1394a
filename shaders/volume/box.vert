#version 450 core
// The cube [0, box] in voxel space as 12 triangles, counter-clockwise seen from outside; no vertex
// buffer (corners come from gl_VertexID). Passes the voxel-space position on for interpolation.
uniform mat4 voxel_to_clip;
uniform vec3 box;  // voxel-space extent (samples, crosslines, inlines)

out vec3 voxel_position;

// Corner k = (k & 1, (k >> 1) & 1, (k >> 2) & 1); faces -x, +x, -y, +y, -z, +z as two triangles.
const int kCorners[36] = int[36](0, 4, 6, 0, 6, 2,   1, 3, 7, 1, 7, 5,
                                 0, 1, 5, 0, 5, 4,   2, 6, 7, 2, 7, 3,
                                 0, 2, 3, 0, 3, 1,   4, 5, 7, 4, 7, 6);

void main() {
    const int k = kCorners[gl_VertexID];
    const vec3 corner = vec3(float(k & 1), float((k >> 1) & 1), float((k >> 2) & 1));
    voxel_position = corner * box;
    gl_Position = voxel_to_clip * vec4(voxel_position, 1.0);
}
