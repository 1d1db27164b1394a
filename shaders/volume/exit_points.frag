#version 450 core
// Pass 1 of the paper: back faces only (front faces culled) give each pixel's ray exit point.
in vec3 voxel_position;
layout(location = 0) out vec4 exit_point;  // xyz: voxel space, w = 1 where a back face was drawn

void main() { exit_point = vec4(voxel_position, 1.0); }
