#version 450 core
// Stage 1, cut volumes (src/cutaway/cut_surface/volume_cut.h): the volumes' triangle corners,
// render space, to the cut camera's eye space; volume.geom builds the cut from each triangle.
layout(location = 0) in vec3 position;

uniform mat4 cut_view;

out VolumeCorner {
    vec3 eye;
} corner;

void main() {
    corner.eye = (cut_view * vec4(position, 1.0)).xyz;
    gl_Position = vec4(0.0);
}
