#version 450 core
#include "common/hsv.glsl"
uniform sampler1D colour_map;

in vec4 v_colour;
in float v_map_t;
in float v_saturation;
layout(location = 0) out vec4 out_colour;

void main() {
    vec3 mapped = texture(colour_map, max(v_map_t, 0.0)).rgb;
    out_colour = v_map_t < 0.0 ? v_colour : vec4(v_saturation == 1.0 ? mapped : scale_saturation(mapped, v_saturation), 1.0);
}
