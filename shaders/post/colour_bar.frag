#version 450 core
uniform sampler1D colour_map;

in vec4 v_colour;
in float v_map_t;
layout(location = 0) out vec4 out_colour;

void main() { out_colour = v_map_t < 0.0 ? v_colour : vec4(texture(colour_map, v_map_t).rgb, 1.0); }
