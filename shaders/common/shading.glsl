// Cell colours and lighting shared by every pass that draws faces.
uniform sampler1D colour_map;   // perceptual map, 256 texels
uniform vec2 value_range;       // property values mapped to the ends of the colour map
uniform vec3 light_eye;         // headlight position (render space): the model camera

vec3 cell_colour(uint compact_cell) {
    float span = value_range.y - value_range.x;
    float t = span > 0.0 ? (texelFetch(cell_value_texels, int(compact_cell)).r - value_range.x) / span : 0.5;
    return texture(colour_map, clamp(t, 0.0, 1.0)).rgb;
}

vec3 lit(vec3 colour, vec3 normal, vec3 world) {
    vec3 to_light = normalize(light_eye - world);
    float diffuse = abs(dot(normalize(normal), to_light));
    return colour * (0.35 + 0.65 * diffuse);
}

#include "common/line_style.glsl"
