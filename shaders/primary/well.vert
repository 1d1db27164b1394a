#version 450 core
// Stage 3: well tubes (src/cutaway/well_tubes.h), triangles in render space.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in uint well;    // index in the renderer's well set
layout(location = 3) in vec4 colour;  // the well's colour (kind, status)

#include "common/cameras.glsl"

out vec3 v_world;
out vec3 v_normal;
out vec3 v_colour;
flat out uint v_well;

void main() {
    gl_Position = view_projection * vec4(position, 1.0);
    v_world = position;
    v_normal = normal;
    v_colour = colour.rgb;
    v_well = well;
}
