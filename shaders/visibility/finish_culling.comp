#version 450 core
// After visibility/cull_cells.comp: the draw command's vertex count from the faces selected,
// clamped to the capacity of the face buffer (an overflow shows as faces_requested > capacity).
layout(local_size_x = 1) in;

layout(std430, binding = 11) buffer Culling {
    uint vertex_count;
    uint instance_count;
    uint first_vertex;
    uint base_instance;
    uint bricks_culled;
    uint cells_culled;
    uint cells_behind;
    uint cells_straddling;
    uint faces_requested;
};

uniform uint face_capacity;

void main() { vertex_count = 6u * min(faces_requested, face_capacity); }
