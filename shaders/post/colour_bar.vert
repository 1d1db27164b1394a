#version 450 core
// Colour bar and its labels, in window pixels (origin top left).
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 colour;
layout(location = 2) in float map_t;       // < 0: solid `colour` (text, frame); else colour map at t
layout(location = 3) in float saturation;  // factor on the colour map's saturation (1: as mapped)

uniform vec2 viewport_size;

out vec4 v_colour;
out float v_map_t;
out float v_saturation;

void main() {
    vec2 ndc = position / viewport_size * 2.0 - 1.0;
    gl_Position = vec4(ndc.x, -ndc.y, 0.0, 1.0);
    v_colour = colour;
    v_map_t = map_t;
    v_saturation = saturation;
}
